// SPDX-License-Identifier: MIT
// satviz: boxes filed by the cells of a uniform grid.

#include "box_grid.h"

#include <algorithm>
#include <cmath>

namespace satviz::detail
{

namespace
{

// Cells a box may span and still be filed: a larger one is read by every search instead.
constexpr int kMaxCellsPerBox = 16;

// The cell along one axis of position v, with `low` the grid's lower bound: monotone in v, so a box from l to u
// spans the cells of l to u, and any point within it falls in one of those.
int CellOf(double v, double low, double cellsPerUnit, int cells)
{
    const double t = (v - low) * cellsPerUnit;
    return t < 1.0 ? 0 : (t < cells ? static_cast<int>(t) : cells - 1);
}

} // namespace

int BoxGrid::CellX(double x) const
{
    return CellOf(x, m_low.x, m_cellsPerUnit, m_columns);
}

int BoxGrid::CellY(double y) const
{
    return CellOf(y, m_low.y, m_cellsPerUnit, m_rows);
}

void BoxGrid::Make(const std::vector<Aabb>& boxes)
{
    const int n = static_cast<int>(boxes.size());
    m_unfiled.clear();
    m_isUnfiled.assign(static_cast<size_t>(n), 0);
    m_seen.assign(static_cast<size_t>(n), 0);
    m_search = 0;
    m_columns = 0;
    m_rows = 0;
    Vec2 low{0.0, 0.0}, high{0.0, 0.0};
    double sides = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const Aabb& box = boxes[static_cast<size_t>(i)];
        low = i == 0 ? box.min : Vec2{std::min(low.x, box.min.x), std::min(low.y, box.min.y)};
        high = i == 0 ? box.max : Vec2{std::max(high.x, box.max.x), std::max(high.y, box.max.y)};
        sides += (box.max.x - box.min.x) + (box.max.y - box.min.y);
    }
    double cell = sides / (2.0 * n);
    const double width = high.x - low.x;
    const double height = high.y - low.y;
    if (n > 0 && std::isfinite(width) && std::isfinite(height) && std::isfinite(cell) && cell > 0.0)
    {
        while ((std::floor(width / cell) + 1.0) * (std::floor(height / cell) + 1.0) > 4.0 * n + 16.0)
        {
            cell *= 2.0;
        }
        m_columns = static_cast<int>(width / cell) + 1;
        m_rows = static_cast<int>(height / cell) + 1;
        m_low = low;
        m_cellsPerUnit = 1.0 / cell;
    }
    const int cells = m_columns * m_rows;
    m_cellStart.assign(static_cast<size_t>(cells) + 1, 0);
    std::vector<int> fill;
    // Two passes over the boxes in order: count each cell's, then file them, so each cell lists its boxes in
    // ascending order.
    for (int pass = 0; pass < 2; ++pass)
    {
        for (int i = 0; i < n; ++i)
        {
            const Aabb& box = boxes[static_cast<size_t>(i)];
            int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
            if (cells > 0)
            {
                x0 = CellX(box.min.x);
                x1 = CellX(box.max.x);
                y0 = CellY(box.min.y);
                y1 = CellY(box.max.y);
            }
            if (cells == 0 || (x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerBox)
            {
                if (pass == 0)
                {
                    Unfile(i);
                }
                continue;
            }
            for (int y = y0; y <= y1; ++y)
            {
                for (int x = x0; x <= x1; ++x)
                {
                    const size_t c = static_cast<size_t>(y) * static_cast<size_t>(m_columns) + static_cast<size_t>(x);
                    if (pass == 0)
                    {
                        ++m_cellStart[c + 1];
                    }
                    else
                    {
                        m_cellBoxes[static_cast<size_t>(fill[c]++)] = i;
                    }
                }
            }
        }
        if (pass == 0)
        {
            for (int c = 0; c < cells; ++c)
            {
                m_cellStart[static_cast<size_t>(c) + 1] += m_cellStart[static_cast<size_t>(c)];
            }
            m_cellBoxes.resize(static_cast<size_t>(m_cellStart[static_cast<size_t>(cells)]));
            fill.assign(m_cellStart.begin(), m_cellStart.end() - 1);
        }
    }
}

void BoxGrid::Unfile(int i)
{
    if (!m_isUnfiled[static_cast<size_t>(i)])
    {
        m_isUnfiled[static_cast<size_t>(i)] = 1;
        m_unfiled.push_back(i);
    }
}

// A box that meets `box` is unfiled, or filed by cells that span a box it has not left, which meets `box` at some
// point: that point's cell is one of those `box` spans.
void BoxGrid::Meeting(const std::vector<Aabb>& boxes, const Aabb& box, int skip, std::vector<int>& met)
{
    met.clear();
    if (++m_search == 0)
    {
        std::fill(m_seen.begin(), m_seen.end(), 0u);
        m_search = 1;
    }
    const auto look = [&](int o) {
        if (o != skip && m_seen[static_cast<size_t>(o)] != m_search)
        {
            m_seen[static_cast<size_t>(o)] = m_search;
            if (AabbOverlap(box, boxes[static_cast<size_t>(o)]))
            {
                met.push_back(o);
            }
        }
    };
    if (m_columns > 0)
    {
        const int x0 = CellX(box.min.x), x1 = CellX(box.max.x);
        const int y0 = CellY(box.min.y), y1 = CellY(box.max.y);
        for (int y = y0; y <= y1; ++y)
        {
            for (int x = x0; x <= x1; ++x)
            {
                const size_t c = static_cast<size_t>(y) * static_cast<size_t>(m_columns) + static_cast<size_t>(x);
                for (int q = m_cellStart[c]; q < m_cellStart[c + 1]; ++q)
                {
                    look(m_cellBoxes[static_cast<size_t>(q)]);
                }
            }
        }
    }
    for (const int o : m_unfiled)
    {
        look(o);
    }
    std::sort(met.begin(), met.end());
}

} // namespace satviz::detail
