// SPDX-License-Identifier: MIT
// satviz: boxes filed by the cells of a uniform grid, for the time of impact's searches of the reaches a box meets
// (internal).
#pragma once

#include <satviz/broadphase.h>

#include <cstdint>
#include <vector>

namespace satviz::detail
{

/// The boxes of a list filed by the cells of a uniform grid over them, so that a search for the boxes one box meets
/// reads the cells it spans instead of every box. A box that spans many cells (a fast body's path), or that has
/// grown since the grid was made (Unfile), is filed nowhere and read by every search.
class BoxGrid
{
  public:
    /// Files `boxes` as they are now. Cells of about a mean box side; at most about four cells per box, however
    /// the boxes spread. Without finite bounds every box is unfiled.
    void Make(const std::vector<Aabb>& boxes);
    /// Box i may change from now on: every search reads it.
    void Unfile(int i);
    /// The boxes of `boxes` (the list given to Make, changed only where unfiled) other than box `skip` that meet
    /// `box` (touching counts), in ascending order, into `met`.
    void Meeting(const std::vector<Aabb>& boxes, const Aabb& box, int skip, std::vector<int>& met);

  private:
    int CellX(double x) const;
    int CellY(double y) const;

    Vec2 m_low{};
    double m_cellsPerUnit = 0.0;
    int m_columns = 0, m_rows = 0; // 0: no grid, every box is unfiled
    std::vector<int> m_cellStart;  // cell c's boxes: m_cellBoxes[m_cellStart[c] .. m_cellStart[c + 1])
    std::vector<int> m_cellBoxes;
    std::vector<int> m_unfiled;
    std::vector<uint8_t> m_isUnfiled;
    std::vector<uint32_t> m_seen; // the search that last read each box
    uint32_t m_search = 0;
};

} // namespace satviz::detail
