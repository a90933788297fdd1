// SPDX-License-Identifier: MIT
// The SVG canvas: the painter's figures as well-formed SVG (checked by a parser written in the tests), one element
// per drawing call with the same text and colours as the recording canvas sees, and the same bytes every time.
#include "support/xml_check.h"

#include <satviz/render/figure.h>
#include <satviz/render/recording_canvas.h>
#include <satviz/render/svg_canvas.h>

#include <catch2/catch.hpp>

#include <cctype>
#include <cstdio>

using namespace satviz;
using satviz::test::CollectElements;
using satviz::test::ParseXml;
using satviz::test::XmlElement;

namespace
{

Scene LoadTutorial(const std::string& name)
{
    SceneResult result = LoadScene(std::string(SATVIZ_SOURCE_DIR) + "/tutorials/scenes/" + name, SceneOptions{true});
    INFO(result.error);
    REQUIRE(result.Ok());
    return result.scene;
}

std::string HexOf(Color color)
{
    char text[8];
    std::snprintf(text, sizeof(text), "#%06x", static_cast<unsigned>(color >> 8));
    return text;
}

const char* ElementOf(const DrawCommand& command)
{
    switch (command.kind)
    {
    case DrawCommand::Kind::Segment:
        return "line";
    case DrawCommand::Kind::Polyline:
        return command.closed ? "polygon" : "polyline";
    case DrawCommand::Kind::FillConvex:
        return "polygon";
    case DrawCommand::Kind::Circle:
    case DrawCommand::Kind::FillCircle:
        return "circle";
    case DrawCommand::Kind::FillRect:
        return "rect";
    case DrawCommand::Kind::Text:
        return "text";
    }
    return "";
}

} // namespace

TEST_CASE("SVG canvas: every figure of the lessons is well-formed SVG, call for call the recording's", "[svg]")
{
    for (const char* name : {"l14_head_on.json", "l06_tilted_plank.json", "l13_overlap.json", "l07_voronoi.json"})
    {
        INFO(name);
        const Scene scene = LoadTutorial(name);
        FigureSetup setup = SetUpFigure(scene, FigureOptions{});
        REQUIRE(setup.Ok());
        RecordingCanvas recording;
        PaintFigure(recording, scene, setup.study, setup.figure);
        SvgCanvas svg(setup.figure.view.width, setup.figure.view.height);
        PaintFigure(svg, scene, setup.study, setup.figure);
        const std::string document = svg.Document();
        const auto parsed = ParseXml(document);
        INFO(parsed.error);
        REQUIRE(parsed.root != nullptr);
        const XmlElement& root = *parsed.root;
        CHECK(root.name == "svg");
        CHECK(root.attributes.at("xmlns") == "http://www.w3.org/2000/svg");
        CHECK(root.attributes.at("width") == std::to_string(setup.figure.view.width));
        CHECK(root.attributes.at("height") == std::to_string(setup.figure.view.height));
        CHECK(root.attributes.at("font-family").rfind("DejaVu Sans", 0) == 0);

        std::vector<const XmlElement*> elements;
        CollectElements(root, elements);
        std::vector<const XmlElement*> drawn;
        for (const XmlElement* element : elements)
        {
            if (element->name != "g")
            {
                drawn.push_back(element);
            }
        }
        // Calls that draw nothing (polylines of fewer than 2 points, fills of fewer than 3) are skipped by both.
        std::vector<const DrawCommand*> calls;
        for (const DrawCommand& command : recording.commands)
        {
            const size_t n = command.points.size();
            if ((command.kind == DrawCommand::Kind::Polyline && n < 2) ||
                (command.kind == DrawCommand::Kind::FillConvex && n < 3))
            {
                continue;
            }
            calls.push_back(&command);
        }
        REQUIRE(drawn.size() == calls.size());
        // A coordinate as the canvas writes it: an optional minus, digits, and at most two decimals. (Written out
        // rather than as a std::regex, whose GCC 12 header trips -Wmaybe-uninitialized under the sanitizers.)
        const auto isNumber = [](const std::string& text) {
            size_t k = text.size() > 0 && text[0] == '-' ? 1 : 0;
            const size_t digits = k;
            while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])))
            {
                ++k;
            }
            if (k == digits)
            {
                return false;
            }
            if (k == text.size())
            {
                return true;
            }
            if (text[k] != '.')
            {
                return false;
            }
            const size_t decimals = text.size() - k - 1;
            for (size_t d = k + 1; d < text.size(); ++d)
            {
                if (!std::isdigit(static_cast<unsigned char>(text[d])))
                {
                    return false;
                }
            }
            return decimals >= 1 && decimals <= 2;
        };
        for (size_t k = 0; k < calls.size(); ++k)
        {
            const DrawCommand& call = *calls[k];
            const XmlElement& element = *drawn[k];
            INFO("call " << k << " in group " << call.group);
            CHECK(element.name == ElementOf(call));
            const bool stroked = call.kind == DrawCommand::Kind::Segment || call.kind == DrawCommand::Kind::Polyline ||
                                 call.kind == DrawCommand::Kind::Circle;
            CHECK(element.attributes.at(stroked ? "stroke" : "fill") == HexOf(call.color));
            if (call.kind == DrawCommand::Kind::Text)
            {
                CHECK(element.text == call.text);
                CHECK(element.attributes.count("font-weight") == (call.style == TextStyle::Heading ? 1u : 0u));
            }
            for (const char* attribute : {"x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height"})
            {
                if (auto it = element.attributes.find(attribute); it != element.attributes.end())
                {
                    CHECK(isNumber(it->second));
                }
            }
        }
        // The same figure painted again gives the same bytes.
        SvgCanvas again(setup.figure.view.width, setup.figure.view.height);
        PaintFigure(again, scene, setup.study, setup.figure);
        CHECK(again.Document() == document);
    }
}

TEST_CASE("SVG canvas: text with markup characters stays text, numbers are rounded to hundredths", "[svg]")
{
    SvgCanvas canvas(100, 50);
    canvas.BeginGroup("a \"group\"");
    canvas.Text({1.0f, 2.0f}, "t < 0.5 & d > \"1\"", TextStyle::Body, 0x11223380u);
    canvas.Segment({0.004f, -0.004f}, {1.0f / 3.0f, 2.675f}, palette::kInk, 1.5f);
    const std::string document = canvas.Document();
    const auto parsed = ParseXml(document);
    INFO(parsed.error << "\n" << document);
    REQUIRE(parsed.root != nullptr);
    std::vector<const XmlElement*> elements;
    CollectElements(*parsed.root, elements);
    REQUIRE(elements.size() == 3);
    CHECK(elements[0]->name == "g");
    const XmlElement& text = *elements[0]->children[0];
    CHECK(text.text == "t < 0.5 & d > \"1\"");
    CHECK(text.attributes.at("fill") == "#112233");
    CHECK(text.attributes.at("fill-opacity") == "0.5");
    // The baseline sits the font's ascent below the top; the em is the pixel height scaled to DejaVu's em.
    CHECK(std::stof(text.attributes.at("y")) == Approx(2.0f + SvgBaseline(TextStyle::Body)).margin(0.006));
    CHECK(std::stof(text.attributes.at("font-size")) == Approx(15.0 * 2048.0 / 2384.0).margin(0.006));
    const XmlElement& line = *elements[0]->children[1];
    CHECK(line.attributes.at("x1") == "0");
    CHECK(line.attributes.at("y1") == "0");
    CHECK(line.attributes.at("x2") == "0.33");
    CHECK(std::abs(std::stod(line.attributes.at("y2")) - 2.675) <= 0.0051);
    CHECK(line.attributes.at("stroke-width") == "1.5");
}
