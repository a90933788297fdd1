// SPDX-License-Identifier: MIT
// satviz app: text wrapped at the edge of the panel between words only (render's WrapLines), where Dear ImGui's
// own wrapping also breaks after '.' and ',' and so splits "(0.00, 1.00)" inside a number.
#pragma once

#include <imgui.h>

#include <string>

namespace satviz
{

/// `text` broken into lines at most `width` pixels wide in the current font, between words only (WrapLines):
/// lines joined by '\n'.
std::string WrapToWidth(const std::string& text, float width);

/// Shows `text` wrapped to the room left on the current line (from the cursor to the window's content edge), in
/// the colour `color` (alpha 0: the text colour of the style).
void WrappedText(const std::string& text, ImVec4 color = ImVec4(0.0f, 0.0f, 0.0f, 0.0f));

/// WrappedText in the style's colour for disabled text.
void WrappedTextDisabled(const std::string& text);

} // namespace satviz
