// SPDX-License-Identifier: MIT
// satviz render: the colours of every figure. Okabe-Ito hues (distinguishable with every common colour-vision
// deficiency) on a warm off-white ground; one meaning per colour, the same in the app and the figures.
#pragma once

#include <cstdint>

namespace satviz
{

/// A colour as 0xRRGGBBAA.
using Color = uint32_t;

/// The same colour with its alpha replaced by `alpha` in [0, 1].
constexpr Color WithAlpha(Color color, float alpha)
{
    const float clamped = alpha < 0.0f ? 0.0f : (alpha > 1.0f ? 1.0f : alpha);
    return (color & 0xFFFFFF00u) | static_cast<uint32_t>(clamped * 255.0f + 0.5f);
}

/// Named colours. Shape A is blue, shape B orange; overlaps are reddish purple, gaps and separating lines bluish
/// green, the minimum translation vector and contacts vermillion.
namespace palette
{
constexpr Color kBackground = 0xFBFAF6FFu; ///< figure ground
constexpr Color kPanel = 0xF1EEE6FFu;      ///< number-line and caption panels
constexpr Color kInk = 0x2B2B2BFFu;        ///< text and strong lines
constexpr Color kMuted = 0x77746EFFu;      ///< secondary text, axes, ticks
constexpr Color kFaint = 0xCFCBC2FFu;      ///< candidate axes, grid
constexpr Color kShapeA = 0x0072B2FFu;     ///< shape A (blue)
constexpr Color kShapeB = 0xE69F00FFu;     ///< shape B (orange)
constexpr Color kShapeBInk = 0xA86F00FFu;  ///< shape B's text and outlines where orange is too light to read
constexpr Color kOther = 0x9A968DFFu;      ///< bodies outside the pair
constexpr Color kOverlap = 0xCC79A7FFu;    ///< an overlap of two intervals (reddish purple)
constexpr Color kGap = 0x009E73FFu;        ///< a gap, a separating axis or line (bluish green)
constexpr Color kResult = 0xD55E00FFu;     ///< the MTV, contact points, the time of impact (vermillion)
constexpr Color kBest = 0x56B4E9FFu;       ///< the best axis so far (sky blue)
} // namespace palette

} // namespace satviz
