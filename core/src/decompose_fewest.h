// SPDX-License-Identifier: MIT
// satviz, private: the fewest convex pieces of a polygon, the exact dynamic programme of decompose.cpp's outline.
#pragma once

#include <satviz/math.h>

#include <vector>

namespace satviz::decompose_detail
{

/// The fewest convex pieces whose corners are vertices of the counter-clockwise simple polygon `v` (no straight
/// vertices): each piece as the indices of its corners, counter-clockwise. O(n^5) at worst.
template <typename S>
std::vector<std::vector<int>> Fewest(const std::vector<Vec2T<S>>& v);

} // namespace satviz::decompose_detail
