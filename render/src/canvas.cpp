// SPDX-License-Identifier: MIT
#include <satviz/render/canvas.h>

namespace satviz
{

float TextSize(TextStyle style)
{
    return style == TextStyle::Label ? 13.0f : 15.0f;
}

} // namespace satviz
