// SPDX-License-Identifier: MIT
// A small XML parser for tests: enough of XML 1.0 to check that a document is well formed (one root element, tags
// nested and closed, attributes quoted and not repeated, only the predefined entities and character references,
// no raw '<' or '&' in text) and to read its elements back. Written here, apart from the code that writes the
// documents, so that it is an independent check.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace satviz::test
{

/// One element: its name, attributes, text (entities resolved) and children, in order.
struct XmlElement
{
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;
    std::vector<std::unique_ptr<XmlElement>> children;
};

/// A parsed document, or the first problem found ("offset 123: ...").
struct XmlDocument
{
    std::unique_ptr<XmlElement> root;
    std::string error;
};

namespace xml_detail
{

inline bool NameChar(char c, bool first)
{
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':';
    return letter || (!first && ((c >= '0' && c <= '9') || c == '-' || c == '.'));
}

struct Parser
{
    const std::string& s;
    size_t i = 0;
    std::string error;

    bool Fail(const std::string& what)
    {
        if (error.empty())
        {
            error = "offset " + std::to_string(i) + ": " + what;
        }
        return false;
    }
    void Space()
    {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r'))
        {
            ++i;
        }
    }
    bool Name(std::string& name)
    {
        const size_t start = i;
        while (i < s.size() && NameChar(s[i], i == start))
        {
            ++i;
        }
        name = s.substr(start, i - start);
        return !name.empty() || Fail("a name expected");
    }
    // Text up to `end` (one of '<' or a quote), with entities resolved.
    bool Chars(char end, std::string& out)
    {
        while (i < s.size() && s[i] != end)
        {
            const char c = s[i];
            if (c == '<')
            {
                return Fail("'<' in an attribute value");
            }
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r')
            {
                return Fail("a control character");
            }
            if (c != '&')
            {
                out += c;
                ++i;
                continue;
            }
            const size_t semi = s.find(';', i);
            if (semi == std::string::npos || semi - i > 8)
            {
                return Fail("'&' that starts no entity");
            }
            const std::string entity = s.substr(i + 1, semi - i - 1);
            static const std::map<std::string, char> named = {
                {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
            if (auto it = named.find(entity); it != named.end())
            {
                out += it->second;
            }
            else if (entity.size() > 1 && entity[0] == '#')
            {
                out += '?'; // a character reference: well formed; its character does not matter to the tests
            }
            else
            {
                return Fail("unknown entity &" + entity + ";");
            }
            i = semi + 1;
        }
        return i < s.size() || Fail("unexpected end of the document");
    }
    bool Element(XmlElement& element)
    {
        ++i; // '<'
        if (!Name(element.name))
        {
            return false;
        }
        for (;;)
        {
            const size_t before = i;
            Space();
            if (i >= s.size())
            {
                return Fail("unexpected end in a tag");
            }
            if (s.compare(i, 2, "/>") == 0)
            {
                i += 2;
                return true;
            }
            if (s[i] == '>')
            {
                ++i;
                break;
            }
            if (i == before)
            {
                return Fail("space expected between attributes");
            }
            std::string name;
            if (!Name(name))
            {
                return false;
            }
            Space();
            if (i >= s.size() || s[i] != '=')
            {
                return Fail("'=' expected after attribute " + name);
            }
            ++i;
            Space();
            if (i >= s.size() || (s[i] != '"' && s[i] != '\''))
            {
                return Fail("a quoted value expected for attribute " + name);
            }
            const char quote = s[i++];
            std::string value;
            if (!Chars(quote, value))
            {
                return false;
            }
            ++i;
            if (!element.attributes.emplace(name, value).second)
            {
                return Fail("attribute " + name + " given twice");
            }
        }
        for (;;)
        {
            std::string text;
            while (i < s.size() && s[i] != '<')
            {
                if (!Chars('<', text))
                {
                    return false;
                }
            }
            element.text += text;
            if (i >= s.size())
            {
                return Fail("<" + element.name + "> is never closed");
            }
            if (s.compare(i, 2, "</") == 0)
            {
                i += 2;
                std::string name;
                if (!Name(name))
                {
                    return false;
                }
                Space();
                if (name != element.name || i >= s.size() || s[i] != '>')
                {
                    return Fail("</" + name + "> closes <" + element.name + ">");
                }
                ++i;
                return true;
            }
            auto child = std::make_unique<XmlElement>();
            if (!Element(*child))
            {
                return false;
            }
            element.children.push_back(std::move(child));
        }
    }
};

} // namespace xml_detail

/// Parses a whole document: an optional XML declaration, one root element, white space around it.
inline XmlDocument ParseXml(const std::string& text)
{
    XmlDocument document;
    xml_detail::Parser parser{text, 0, {}};
    if (text.compare(0, 5, "<?xml") == 0)
    {
        const size_t end = text.find("?>");
        if (end == std::string::npos)
        {
            document.error = "the XML declaration is not closed";
            return document;
        }
        parser.i = end + 2;
    }
    parser.Space();
    if (parser.i >= text.size() || text[parser.i] != '<')
    {
        document.error = "no root element";
        return document;
    }
    auto root = std::make_unique<XmlElement>();
    if (!parser.Element(*root))
    {
        document.error = parser.error;
        return document;
    }
    parser.Space();
    if (parser.i != text.size())
    {
        parser.Fail("content after the root element");
        document.error = parser.error;
        return document;
    }
    document.root = std::move(root);
    return document;
}

/// Every element below `element` (depth first, in document order), itself excluded.
inline void CollectElements(const XmlElement& element, std::vector<const XmlElement*>& out)
{
    for (const auto& child : element.children)
    {
        out.push_back(child.get());
        CollectElements(*child, out);
    }
}

} // namespace satviz::test
