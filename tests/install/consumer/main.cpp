// SPDX-License-Identifier: MIT
// A program built against the installed satviz (satviz::core): two boxes that overlap and two that do not.
#include <satviz/sat.h>

#include <cmath>
#include <cstdio>

int main()
{
    using namespace satviz;
    const Polygon box = MakeBox(1.0, 0.5).polygon; // half-widths: 2 by 1
    const Transform atOrigin = MakeTransform(Vec2{0.0, 0.0}, 0.0);
    const Transform overlapping = MakeTransform(Vec2{1.5, 0.2}, 0.0); // 0.5 into the first box along x
    const Transform apart = MakeTransform(Vec2{2.5, 0.0}, 0.0);       // 0.5 beyond it

    const bool hit = Overlap(box, atOrigin, box, overlapping);
    const bool miss = Overlap(box, atOrigin, box, apart);
    const Manifold m = Collide(box, atOrigin, box, overlapping);
    const bool ok = hit && !miss && m.overlap && std::abs(m.depth - 0.5) < 1e-12 &&
                    std::abs(m.normal.x - 1.0) < 1e-12 && std::abs(m.normal.y) < 1e-12;
    std::printf("consumer: overlap %d, apart %d, depth %.17g, normal (%g, %g): %s\n", hit, miss, m.depth, m.normal.x,
                m.normal.y, ok ? "as expected" : "WRONG");
    return ok ? 0 : 1;
}
