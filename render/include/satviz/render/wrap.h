// SPDX-License-Identifier: MIT
// satviz render: text wrapped between words only, for the figures' captions and the app's panels alike, so that a
// number is never broken inside its digits nor split from its partner in a bracketed pair or from its unit.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace satviz
{

/// The words of `text` that a line may break between: the text split at its spaces, where a bracketed pair or list
/// of numbers ("[-0.25, 0.25]", "(0.96, 0.30)": numbers, commas, spaces and signs only), an equation's sides
/// ("t = 0.438", "a + 0.30 × (0.00, 1.00)": "=", "+", "×" and "−" join their sides, a number the pair it scales) and a
/// number with its unit ("0.417 s)", "3 m/s", "0.5 N s") stay one word. Prose in parentheses splits, even when it opens with a number ("(0.1645 in full;").
std::vector<std::string> WrapWords(const std::string& text);

/// `text` broken into lines no wider than `width` as `measure` measures them, greedily, between the words of
/// WrapWords only, except that a word wider than `width` goes on over as many lines as it needs, so that nothing is
/// cut at the panel's edge: a web address (a word with "://") broken after a '/' or before a '.', '-', '?', '#',
/// '&', '=' or '_' where it can, any other word after a ',', ':', ';', ')' or ']', before a bracket or at a space,
/// and a pair of numbers only when nothing else fits; failing those, anywhere between characters. A newline in `text`
/// always ends a line (an empty line stays empty); leading spaces of a line are kept on its first line.
std::vector<std::string> WrapLines(const std::string& text, float width,
                                   const std::function<float(const std::string&)>& measure);

} // namespace satviz
