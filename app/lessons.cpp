// SPDX-License-Identifier: MIT
#include "lessons.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <md4c.h>
#include <sstream>

namespace satviz
{

namespace
{

namespace fs = std::filesystem;

// md4c's callbacks fill this: the blocks so far and the one being read.
struct Reader
{
    std::vector<LessonBlock> blocks;
    LessonBlock current;
    bool open = false;    // a text block is being read
    int listDepth = 0;    // nesting of lists
    std::vector<int> listNumbers; // per open list, the next item's number (0: a bullet list)
    bool inImage = false; // inside an image span: text is its alternative text
    LessonBlock image;
    bool inCell = false; // inside a table row: cells are joined
    bool firstCell = true;
    int quoteDepth = 0;     // nesting of block quotes
    int details = 0;        // the <details> section being read (0: none)
    int detailsCount = 0;   // sections so far
    bool inSummary = false; // inside <summary>: text is the section's title
    std::string summary;

    void Begin(LessonBlock::Kind kind, int level)
    {
        Finish();
        current = LessonBlock{};
        current.kind = kind;
        current.level = level;
        current.quote = quoteDepth > 0;
        current.details = details;
        current.summary = details > 0 ? summary : std::string();
        open = true;
    }

    void Finish()
    {
        if (!open)
        {
            return;
        }
        open = false;
        // Trim the spaces soft breaks leave at either end.
        std::string& t = current.text;
        t.erase(t.begin(), std::find_if(t.begin(), t.end(), [](unsigned char c) { return !std::isspace(c); }));
        while (!t.empty() && current.kind != LessonBlock::Kind::Code &&
               std::isspace(static_cast<unsigned char>(t.back())))
        {
            t.pop_back();
        }
        if (!t.empty() || current.kind == LessonBlock::Kind::Rule)
        {
            blocks.push_back(current);
        }
    }

    void Append(const std::string& text)
    {
        if (inSummary)
        {
            summary += text;
        }
        else if (inImage)
        {
            image.text += text;
        }
        else if (open)
        {
            if (inCell && !current.cells.empty())
            {
                current.cells.back() += text;
            }
            current.text += text;
        }
    }
};

// The figure fonts hold Latin-1 only: the few mathematical signs the lessons use beyond it are written the way
// plain text writes them.
std::string Latin1(std::string text)
{
    static const std::pair<const char*, const char*> kSigns[] = {
        {"\u2212", "-"}, {"\u2013", "-"},    {"\u2014", " - "}, {"\u2264", "<="},  {"\u2265", ">="},
        {"\u2248", "~"}, {"\u221a", "sqrt"}, {"\u2192", "->"},  {"\u2026", "..."}, {"\u2011", "-"},
    };
    for (const auto& [from, to] : kSigns)
    {
        for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + std::strlen(to)))
        {
            text.replace(at, std::strlen(from), to);
        }
    }
    return text;
}

int EnterBlock(MD_BLOCKTYPE type, void* detail, void* user)
{
    Reader& r = *static_cast<Reader*>(user);
    switch (type)
    {
    case MD_BLOCK_H:
        r.Begin(LessonBlock::Kind::Heading, static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level));
        break;
    case MD_BLOCK_P:
        // A paragraph inside a list item continues the item.
        if (!(r.open && r.current.kind == LessonBlock::Kind::Item))
        {
            r.Begin(LessonBlock::Kind::Paragraph, 0);
        }
        break;
    case MD_BLOCK_UL:
        ++r.listDepth;
        r.listNumbers.push_back(0);
        break;
    case MD_BLOCK_OL:
        ++r.listDepth;
        r.listNumbers.push_back(static_cast<int>(static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start));
        break;
    case MD_BLOCK_LI:
        r.Begin(LessonBlock::Kind::Item, r.listDepth);
        if (!r.listNumbers.empty() && r.listNumbers.back() > 0)
        {
            r.current.number = r.listNumbers.back()++;
        }
        break;
    case MD_BLOCK_CODE:
        r.Begin(LessonBlock::Kind::Code, 0);
        break;
    case MD_BLOCK_HR:
        r.Begin(LessonBlock::Kind::Rule, 0);
        r.Finish();
        break;
    case MD_BLOCK_QUOTE:
        r.Finish();
        ++r.quoteDepth;
        break;
    case MD_BLOCK_TR:
        r.Begin(LessonBlock::Kind::Paragraph, 0);
        r.inCell = true;
        r.firstCell = true;
        break;
    case MD_BLOCK_TH:
    case MD_BLOCK_TD:
        r.current.text += r.firstCell ? "" : " | ";
        r.firstCell = false;
        r.current.cells.emplace_back();
        r.current.header = r.current.header || type == MD_BLOCK_TH;
        break;
    default:
        break;
    }
    return 0;
}

int LeaveBlock(MD_BLOCKTYPE type, void*, void* user)
{
    Reader& r = *static_cast<Reader*>(user);
    switch (type)
    {
    case MD_BLOCK_H:
    case MD_BLOCK_CODE:
    case MD_BLOCK_LI:
        r.Finish();
        break;
    case MD_BLOCK_P:
        if (!(r.open && r.current.kind == LessonBlock::Kind::Item))
        {
            r.Finish();
        }
        else
        {
            r.Append(" ");
        }
        break;
    case MD_BLOCK_UL:
    case MD_BLOCK_OL:
        --r.listDepth;
        r.listNumbers.pop_back();
        break;
    case MD_BLOCK_QUOTE:
        r.Finish();
        --r.quoteDepth;
        break;
    case MD_BLOCK_TR:
        r.inCell = false;
        r.Finish();
        break;
    default:
        break;
    }
    return 0;
}

int EnterSpan(MD_SPANTYPE type, void* detail, void* user)
{
    Reader& r = *static_cast<Reader*>(user);
    if (type == MD_SPAN_IMG)
    {
        const MD_SPAN_IMG_DETAIL* img = static_cast<MD_SPAN_IMG_DETAIL*>(detail);
        r.inImage = true;
        r.image = LessonBlock{};
        r.image.kind = LessonBlock::Kind::Figure;
        r.image.target.assign(img->src.text, img->src.size);
    }
    return 0;
}

int LeaveSpan(MD_SPANTYPE type, void*, void* user)
{
    Reader& r = *static_cast<Reader*>(user);
    if (type == MD_SPAN_IMG)
    {
        r.inImage = false;
        // A figure stands on its own between the text before and after it.
        const bool wasOpen = r.open;
        const LessonBlock::Kind kind = r.current.kind;
        const int level = r.current.level;
        r.Finish();
        r.blocks.push_back(r.image);
        if (wasOpen)
        {
            r.Begin(kind, level);
        }
    }
    return 0;
}

int Text(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user)
{
    Reader& r = *static_cast<Reader*>(user);
    const std::string s(text, size);
    switch (type)
    {
    case MD_TEXT_HTML:
        // <details><summary>S</summary> ... </details>: a section shown collapsed under S. The lessons' check
        // marks and other HTML are not shown.
        if (s == "<details>")
        {
            // The paragraph the tags open holds the summary only: it is no block of its own.
            r.Finish();
            r.details = ++r.detailsCount;
            r.summary.clear();
        }
        else if (s == "<summary>")
        {
            r.inSummary = true;
        }
        else if (s == "</summary>")
        {
            r.inSummary = false;
            const size_t first = r.summary.find_first_not_of(' ');
            r.summary = first == std::string::npos ? "Details" : r.summary.substr(first);
            while (r.summary.back() == ' ')
            {
                r.summary.pop_back();
            }
        }
        else if (s == "</details>")
        {
            r.Finish();
            r.details = 0;
        }
        break;
    case MD_TEXT_BR:
        r.Append(r.current.kind == LessonBlock::Kind::Code ? "\n" : " ");
        break;
    case MD_TEXT_SOFTBR:
        r.Append(" ");
        break;
    case MD_TEXT_ENTITY:
        r.Append(s == "&amp;" ? "&" : s == "&lt;" ? "<" : s == "&gt;" ? ">" : s == "&quot;" ? "\"" : s);
        break;
    default:
        r.Append(Latin1(s));
        break;
    }
    return 0;
}

std::string ReadAll(const std::string& file, bool& ok)
{
    std::ifstream in(file, std::ios::binary);
    ok = static_cast<bool>(in);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

std::vector<LessonBlock> ParseLesson(const std::string& markdown)
{
    MD_PARSER parser{};
    parser.abi_version = 0;
    parser.flags = MD_FLAG_TABLES | MD_FLAG_NOHTMLBLOCKS;
    parser.enter_block = EnterBlock;
    parser.leave_block = LeaveBlock;
    parser.enter_span = EnterSpan;
    parser.leave_span = LeaveSpan;
    parser.text = Text;
    Reader reader;
    md_parse(markdown.data(), static_cast<MD_SIZE>(markdown.size()), &parser, &reader);
    reader.Finish();
    return reader.blocks;
}

bool LoadLesson(const std::string& file, std::vector<LessonBlock>& blocks, std::string& error)
{
    bool ok = false;
    const std::string text = ReadAll(file, ok);
    if (!ok)
    {
        error = file + ": cannot read the lesson";
        return false;
    }
    blocks = ParseLesson(text);
    return true;
}

std::vector<std::string> NamedScenes(const std::string& markdown)
{
    std::vector<std::string> names;
    const std::string marker = "scenes/";
    for (size_t at = markdown.find(marker); at != std::string::npos; at = markdown.find(marker, at + 1))
    {
        size_t end = at + marker.size();
        while (end < markdown.size() &&
               (std::isalnum(static_cast<unsigned char>(markdown[end])) || markdown[end] == '_' ||
                markdown[end] == '/'))
        {
            ++end;
        }
        const std::string name = markdown.substr(at + marker.size(), end - at - marker.size());
        if (!name.empty() && markdown.compare(end, 5, ".json") == 0 &&
            std::find(names.begin(), names.end(), name) == names.end())
        {
            names.push_back(name);
        }
    }
    return names;
}

std::string SceneOfFigure(const std::string& figure)
{
    std::string stem = fs::path(figure).stem().string();
    size_t digits = stem.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(stem[digits - 1])))
    {
        --digits;
    }
    if (digits < stem.size() && digits >= 5 && stem.compare(digits - 5, 5, "-step") == 0)
    {
        stem.erase(digits - 5);
    }
    return stem;
}

int FigureStep(const std::string& figure)
{
    const std::string stem = fs::path(figure).stem().string();
    size_t digits = stem.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(stem[digits - 1])))
    {
        --digits;
    }
    if (digits == stem.size() || digits < 5 || stem.compare(digits - 5, 5, "-step") != 0 || stem.size() - digits > 6)
    {
        return -1;
    }
    return std::max(0, std::stoi(stem.substr(digits)) - 1);
}

bool FigureOfFaces(const std::string& figure)
{
    return fs::path(figure).parent_path().filename() == "faces";
}

std::string FigureSceneFile(const std::string& folder, const std::string& figure)
{
    const std::string name = SceneOfFigure(figure) + ".json";
    const fs::path scenes = fs::path(folder) / "scenes";
    std::error_code code;
    if (fs::is_regular_file(scenes / name, code))
    {
        return (scenes / name).string();
    }
    // The scenes of a topic of their own (scenes/concave/...).
    std::vector<fs::path> found;
    for (fs::directory_iterator it(scenes, code), end; !code && it != end; it.increment(code))
    {
        if (it->is_directory(code) && fs::is_regular_file(it->path() / name, code))
        {
            found.push_back(it->path() / name);
        }
    }
    std::sort(found.begin(), found.end());
    return found.empty() ? std::string() : found.front().string();
}

namespace
{

// NN-slug.md: two digits, a dash, letters, digits and dashes.
bool IsLessonFile(const std::string& name)
{
    if (name.size() < 7 || !std::isdigit(static_cast<unsigned char>(name[0])) ||
        !std::isdigit(static_cast<unsigned char>(name[1])) || name[2] != '-' ||
        name.compare(name.size() - 3, 3, ".md") != 0)
    {
        return false;
    }
    return std::all_of(name.begin() + 3, name.end() - 3,
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; });
}

} // namespace

std::vector<Lesson> FindLessons(const std::string& folder)
{
    std::vector<Lesson> lessons;
    std::error_code code;
    for (fs::directory_iterator it(folder, code), end; !code && it != end; it.increment(code))
    {
        const std::string file = it->path().filename().string();
        if (!IsLessonFile(file))
        {
            continue;
        }
        Lesson lesson;
        lesson.file = it->path().string();
        bool ok = false;
        const std::string text = ReadAll(lesson.file, ok);
        for (const LessonBlock& block : ParseLesson(text))
        {
            if (block.kind == LessonBlock::Kind::Heading)
            {
                lesson.title = block.text;
                break;
            }
        }
        if (lesson.title.empty())
        {
            lesson.title = file;
        }
        // The scenes of its figures and those its text names, in order of first mention; the scene of its first
        // figure first of all, which the lesson opens on.
        std::vector<std::pair<size_t, std::string>> mentioned;
        std::string first;
        for (const LessonBlock& block : ParseLesson(text))
        {
            if (block.kind != LessonBlock::Kind::Figure)
            {
                continue;
            }
            const std::string scene = FigureSceneFile(folder, block.target);
            if (!scene.empty())
            {
                if (first.empty())
                {
                    first = scene;
                    lesson.firstStep = FigureStep(block.target);
                    lesson.firstFaces = FigureOfFaces(block.target);
                }
                mentioned.emplace_back(text.find(block.target), scene);
            }
        }
        for (const std::string& name : NamedScenes(text))
        {
            mentioned.emplace_back(text.find("scenes/" + name + ".json"),
                                   (fs::path(folder) / "scenes" / (name + ".json")).string());
        }
        std::stable_sort(mentioned.begin(), mentioned.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        if (!first.empty())
        {
            lesson.scenes.push_back(first);
        }
        for (const auto& [at, scene] : mentioned)
        {
            if (std::find(lesson.scenes.begin(), lesson.scenes.end(), scene) == lesson.scenes.end())
            {
                lesson.scenes.push_back(scene);
            }
        }
        lessons.push_back(lesson);
    }
    std::sort(lessons.begin(), lessons.end(), [](const Lesson& a, const Lesson& b) { return a.file < b.file; });
    return lessons;
}

} // namespace satviz
