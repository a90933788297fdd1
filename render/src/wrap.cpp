// SPDX-License-Identifier: MIT
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace satviz
{

namespace
{

// A web address wider than the line, in pieces that fit: broken after a '/' or before a '.', '-', '?', '#', '&',
// '=' or '_', where a reader still sees one address going on, and only failing those after the last character that
// fits (never inside a UTF-8 character).
std::vector<std::string> BreakLink(const std::string& link, float width,
                                   const std::function<float(const std::string&)>& measure)
{
    std::vector<std::string> pieces;
    size_t start = 0;
    while (start < link.size())
    {
        if (measure(link.substr(start)) <= width)
        {
            pieces.push_back(link.substr(start));
            break;
        }
        size_t natural = 0;
        size_t fits = 0;
        for (size_t length = 1; start + length < link.size(); ++length)
        {
            const char next = link[start + length];
            if ((static_cast<unsigned char>(next) & 0xC0) == 0x80)
            {
                continue;
            }
            if (measure(link.substr(start, length)) > width)
            {
                break;
            }
            fits = length;
            const char previous = link[start + length - 1];
            if ((previous == '/' && next != '/') || std::strchr(".-?#&=_", next) != nullptr)
            {
                natural = length;
            }
        }
        size_t take = natural > 0 ? natural : fits;
        if (take == 0)
        {
            // Not even one character fits: one anyway, whole.
            take = 1;
            while (start + take < link.size() && (static_cast<unsigned char>(link[start + take]) & 0xC0) == 0x80)
            {
                ++take;
            }
        }
        pieces.push_back(link.substr(start, take));
        start += take;
    }
    return pieces;
}

} // namespace

std::vector<std::string> WrapWords(const std::string& text)
{
    std::vector<std::string> words;
    int depth = 0;
    size_t start = 0;
    while (start <= text.size())
    {
        size_t end = text.find(' ', start);
        if (end == std::string::npos)
        {
            end = text.size();
        }
        const std::string word = text.substr(start, end - start);
        // "t = 0.438" stays on one line: "=" joins the words on both sides of it.
        const bool glued = depth > 0 || word == "=" ||
                           (!words.empty() && words.back().size() >= 2 &&
                            words.back().compare(words.back().size() - 2, 2, " =") == 0);
        if (glued && !words.empty() && !word.empty())
        {
            words.back() += " " + word;
        }
        else if (!word.empty())
        {
            words.push_back(word);
        }
        for (size_t i = 0; i < word.size(); ++i)
        {
            // Only a bracket that opens a number ("[-0.25," or "(0.96,") groups; prose in parentheses wraps.
            const bool number = i + 1 < word.size() &&
                                (std::isdigit(static_cast<unsigned char>(word[i + 1])) || word[i + 1] == '-');
            depth += ((word[i] == '[' || word[i] == '(') && number) ? 1 : 0;
            depth -= (word[i] == ']' || word[i] == ')') && depth > 0 ? 1 : 0;
        }
        depth = std::max(depth, 0);
        start = end + 1;
    }
    return words;
}

std::vector<std::string> WrapLines(const std::string& text, float width,
                                   const std::function<float(const std::string&)>& measure)
{
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size())
    {
        size_t end = text.find('\n', start);
        if (end == std::string::npos)
        {
            end = text.size();
        }
        const std::string paragraph = text.substr(start, end - start);
        // A code line's indentation stays in front of its first word.
        const size_t first = paragraph.find_first_not_of(' ');
        const std::string indent = first == std::string::npos ? paragraph : paragraph.substr(0, first);
        std::string line;
        for (const std::string& word : WrapWords(paragraph))
        {
            const std::string candidate = line.empty() ? indent + word : line + " " + word;
            if (word.find("://") != std::string::npos && measure(word) > width)
            {
                // A link that would run past the edge alone starts a line and goes on over the next ones.
                if (!line.empty())
                {
                    lines.push_back(line);
                }
                std::vector<std::string> pieces = BreakLink(word, width, measure);
                lines.insert(lines.end(), pieces.begin(), pieces.end() - 1);
                line = pieces.back();
                continue;
            }
            if (!line.empty() && measure(candidate) > width)
            {
                lines.push_back(line);
                line = word;
            }
            else
            {
                line = candidate;
            }
        }
        lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

} // namespace satviz
