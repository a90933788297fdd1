// SPDX-License-Identifier: MIT
#include <satviz/render/canvas.h>

namespace satviz
{

namespace
{

// Advance widths of the printable ASCII characters (space to '~') in the figures' fonts, DejaVu Sans and DejaVu Sans
// Bold, in font units; a font of pixel size s draws a unit as s / 2384 pixels (2384: the fonts' ascent plus
// descent), as Dear ImGui scales them. Measuring with them, a
// canvas without the fonts (a recording, an SVG) lays a figure out as the PNG figures are laid out.
constexpr int kRegular[95] = {
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716, 1087,
    2048, 1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767, 1532, 1612,
    1235, 1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690, 799, 1716, 1024,
    1024, 1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186, 569, 1995, 1298, 1253,
    1300, 1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075, 1303, 690, 1303, 1716};
constexpr int kBold[95] = {
    713, 934, 1067, 1716, 1425, 2052, 1786, 627, 936, 936, 1071, 1716, 778, 850, 778, 748,
    1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 819, 819, 1716, 1716, 1716, 1188,
    2048, 1585, 1561, 1503, 1700, 1399, 1399, 1681, 1714, 762, 762, 1587, 1305, 2038, 1714, 1741,
    1501, 1741, 1577, 1475, 1397, 1663, 1585, 2259, 1579, 1483, 1485, 936, 748, 936, 1716, 1024,
    1024, 1382, 1466, 1214, 1466, 1389, 891, 1466, 1458, 702, 702, 1362, 702, 2134, 1458, 1407,
    1466, 1466, 1010, 1219, 979, 1458, 1335, 1892, 1321, 1335, 1192, 1458, 748, 1458, 1716};
constexpr float kUnitsPerLine = 2384.0f;

} // namespace

float TextSize(TextStyle style)
{
    return style == TextStyle::Label ? 13.0f : 15.0f;
}

ScreenPoint FontTextSize(std::string_view text, TextStyle style)
{
    const float size = TextSize(style);
    const int* advances = style == TextStyle::Heading ? kBold : kRegular;
    float units = 0.0f;
    for (size_t i = 0; i < text.size(); ++i)
    {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 32 && c < 127)
        {
            units += static_cast<float>(advances[c - 32]);
        }
        else if ((c & 0xC0) != 0x80)
        {
            // Beyond ASCII: one advance per character (not per UTF-8 byte), as wide as an 'M'.
            units += static_cast<float>(advances['M' - 32]);
        }
    }
    return {units * size / kUnitsPerLine, size};
}

} // namespace satviz
