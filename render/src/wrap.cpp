// SPDX-License-Identifier: MIT
#include <satviz/render/wrap.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>

namespace satviz
{

namespace
{

// The index of the bracket that closes a pair or list of numbers opened at `open` ("(0.96, 0.28)",
// "[-0.25, 0.5]": digits, points, commas, spaces and signs only, a digit at least), or npos when the bracket opens
// prose ("(0.1645 in full; ...)"), which wraps like any text.
size_t NumberTupleEnd(const std::string& text, size_t open)
{
    const char close = text[open] == '(' ? ')' : ']';
    bool digit = false;
    for (size_t i = open + 1; i < text.size(); ++i)
    {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == static_cast<unsigned char>(close))
        {
            return digit ? i : std::string::npos;
        }
        if (std::isdigit(c))
        {
            digit = true;
        }
        else if (text.compare(i, 3, "\xE2\x88\x92") == 0) // U+2212 MINUS SIGN
        {
            i += 2;
        }
        else if (std::strchr(".,+- ", static_cast<char>(c)) == nullptr || c == 0)
        {
            return std::string::npos;
        }
    }
    return std::string::npos;
}

// Whether `word`, less the punctuation after it ("s)" or "m/s,"), is a unit of measure.
bool IsUnit(const std::string& word)
{
    static const char* const kUnits[] = {"s",   "m",     "m/s",     "m/s^2", "m/s\xC2\xB2", "rad", "rad/s", "kg",
                                         "N",   "J",     "px",      "ms",    "mm",            "cm",  "degrees",
                                         "m^2", "kg/m^2"};
    const size_t end = word.find_last_not_of(")],.;:*");
    if (end == std::string::npos)
    {
        return false;
    }
    const std::string bare = word.substr(0, end + 1);
    return std::any_of(std::begin(kUnits), std::end(kUnits), [&](const char* unit) { return bare == unit; });
}

// Whether `word` closes a number glued to a unit after it: a number ("0.417", "-3"), or a number and a unit that a
// second part of the unit may follow ("0.5 N" of "0.5 N s", "0.1 kg" of "0.1 kg m^2").
bool TakesUnit(const std::string& word)
{
    if (!word.empty() && std::isdigit(static_cast<unsigned char>(word.back())))
    {
        return true;
    }
    const size_t space = word.rfind(' ');
    if (space == std::string::npos || space == 0 ||
        !std::isdigit(static_cast<unsigned char>(word[space - 1])))
    {
        return false;
    }
    const std::string last = word.substr(space + 1);
    return last == "N" || last == "kg";
}

// Whether `word` is an operator that joins the words on both sides of it: "=", "+", "×" or "−" (U+2212).
bool IsOperator(const std::string& word)
{
    return word == "=" || word == "+" || word == "\xC3\x97" || word == "\xE2\x88\x92";
}

// Whether the last word of `word` (after its last space) is such an operator.
bool EndsWithOperator(const std::string& word)
{
    const size_t space = word.rfind(' ');
    return space != std::string::npos && IsOperator(word.substr(space + 1));
}

// Whether `word` is a plain number: digits with a point or a leading sign ("0.30", "-2"), nothing else.
bool IsNumber(const std::string& word)
{
    bool digit = false;
    for (size_t i = 0; i < word.size(); ++i)
    {
        const char c = word[i];
        if (std::isdigit(static_cast<unsigned char>(c)))
        {
            digit = true;
        }
        else if (!(c == '.' || (i == 0 && (c == '-' || c == '+'))))
        {
            return false;
        }
    }
    return digit;
}

// Whether `word` is a group of three digits that goes on a number written in groups ("000" of "100 000", "000 m/s,"):
// three digits, then nothing or anything but a digit.
bool IsDigitGroup(const std::string& word)
{
    return word.size() >= 3 && std::isdigit(static_cast<unsigned char>(word[0])) &&
           std::isdigit(static_cast<unsigned char>(word[1])) && std::isdigit(static_cast<unsigned char>(word[2])) &&
           (word.size() == 3 || !std::isdigit(static_cast<unsigned char>(word[3])));
}

// Whether `word` ends in a number's first group: one to three digits, after a sign or a bracket if any ("100",
// "(-12"), or a group that a group follows ("100 000").
bool EndsWithShortNumber(const std::string& word)
{
    size_t digits = 0;
    while (digits < word.size() && std::isdigit(static_cast<unsigned char>(word[word.size() - 1 - digits])))
    {
        ++digits;
    }
    if (digits == 0 || digits > 3)
    {
        return false;
    }
    const size_t before = word.size() - digits;
    return before == 0 || std::strchr(" -([", word[before - 1]) != nullptr;
}

// A word wider than the line, in pieces that fit, so that nothing of it is cut at the panel's edge. A web address
// breaks after a '/' or before a '.', '-', '?', '#', '&', '=' or '_', where a reader still sees one address going
// on; any other word after a ',', ':', ';', ')' or ']', before a bracket or at a space (an equation kept as one
// word has them), as in "[-0.2,0.2],", and inside a pair of numbers only when nothing else fits; failing all of
// those after the last character that fits (never inside a UTF-8 character). A number is not parted from its
// unit unless nothing else fits.
std::vector<std::string> BreakWord(const std::string& word, float width,
                                   const std::function<float(const std::string&)>& measure)
{
    const bool link = word.find("://") != std::string::npos;
    // Where a pair of numbers glued into the word (by an "=") lies: broken there only when nothing else will do.
    std::vector<bool> inTuple(word.size(), false);
    for (size_t i = 0; i < word.size(); ++i)
    {
        if (word[i] == '(' || word[i] == '[')
        {
            const size_t close = NumberTupleEnd(word, i);
            for (size_t j = i + 1; close != std::string::npos && j <= close; ++j)
            {
                inTuple[j] = true;
            }
        }
    }
    // A space between a number and its unit ("0.0245 N s" at the end of an equation): kept too, unless nothing
    // else fits.
    for (size_t i = 1; i < word.size(); ++i)
    {
        if (word[i] == ' ' && TakesUnit(word.substr(0, i)) && IsUnit(word.substr(i + 1, word.find(' ', i + 1) - i - 1)))
        {
            inTuple[i] = true;
        }
    }
    std::vector<std::string> pieces;
    size_t start = 0;
    while (start < word.size())
    {
        if (measure(word.substr(start)) <= width)
        {
            pieces.push_back(word.substr(start));
            break;
        }
        size_t natural = 0;
        size_t inside = 0;
        size_t fits = 0;
        for (size_t length = 1; start + length < word.size(); ++length)
        {
            const char next = word[start + length];
            if ((static_cast<unsigned char>(next) & 0xC0) == 0x80)
            {
                continue;
            }
            std::string piece = word.substr(start, length);
            while (!piece.empty() && piece.back() == ' ')
            {
                piece.pop_back();
            }
            if (measure(piece) > width)
            {
                break;
            }
            fits = length;
            const char previous = word[start + length - 1];
            const bool breaks =
                link ? ((previous == '/' && next != '/') || std::strchr(".-?#&=_", next) != nullptr)
                     : (std::strchr(",:;])", previous) != nullptr || std::strchr(" ([", next) != nullptr);
            if (breaks)
            {
                (inTuple[start + length] ? inside : natural) = length;
            }
        }
        size_t take = natural > 0 ? natural : inside > 0 ? inside : fits;
        if (take == 0)
        {
            // Not even one character fits: one anyway, whole.
            take = 1;
            while (start + take < word.size() && (static_cast<unsigned char>(word[start + take]) & 0xC0) == 0x80)
            {
                ++take;
            }
        }
        std::string piece = word.substr(start, take);
        while (!piece.empty() && piece.back() == ' ')
        {
            piece.pop_back();
        }
        if (!piece.empty())
        {
            pieces.push_back(piece);
        }
        start += take;
        while (start < word.size() && word[start] == ' ')
        {
            ++start;
        }
    }
    if (pieces.empty())
    {
        pieces.push_back(word);
    }
    return pieces;
}

} // namespace

std::vector<std::string> WrapWords(const std::string& text)
{
    std::vector<std::string> words;
    // The words up to this index of `text` join the word before them: the inside of a pair of numbers.
    size_t tupleEnd = 0;
    bool inTuple = false;
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
        // "0.417 s)" and "3 m/s" too: a number and its unit are read as one.
        // "a + 0.30 (0.00, 1.00)" too: "+", "×" and "−" join the words on both sides of them as "=" does, and a
        // number joins the pair of numbers after it that it scales.
        const bool glued = (inTuple && start <= tupleEnd) || IsOperator(word) ||
                           (!words.empty() && IsDigitGroup(word) && EndsWithShortNumber(words.back())) ||
                           (!words.empty() && EndsWithOperator(words.back())) ||
                           (!words.empty() && IsUnit(word) && TakesUnit(words.back())) ||
                           (!words.empty() && IsNumber(words.back()) && start < text.size() && text[start] == '(' &&
                            NumberTupleEnd(text, start) != std::string::npos);
        if (glued && !words.empty() && !word.empty())
        {
            words.back() += " " + word;
        }
        else if (!word.empty())
        {
            words.push_back(word);
        }
        if (inTuple && tupleEnd < end)
        {
            inTuple = false;
        }
        for (size_t i = start; i < end; ++i)
        {
            // Only a bracket that opens numbers alone ("[-0.25, 0.5]", "(0.96, 0.28)") groups; prose wraps.
            if (!inTuple && (text[i] == '[' || text[i] == '('))
            {
                const size_t close = NumberTupleEnd(text, i);
                if (close != std::string::npos && close >= end)
                {
                    inTuple = true;
                    tupleEnd = close;
                }
            }
        }
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
            if (measure((line.empty() ? indent : std::string()) + word) > width)
            {
                // A word that would run past the edge even alone starts a line and goes on over the next ones.
                if (!line.empty())
                {
                    lines.push_back(line);
                }
                std::vector<std::string> pieces = BreakWord(word, width, measure);
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
