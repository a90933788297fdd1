// SPDX-License-Identifier: MIT
#include "study_numbers.h"

#include <satviz/render/describe.h>

namespace satviz
{

std::string PanelNumber(double value, const PairStudy& study, bool allDigits)
{
    if (!allDigits)
    {
        return FormatNumber(value);
    }
    // In single precision the queries ran on floats: their numbers are floats widened, shown as floats.
    return study.singlePrecision ? FullDecimal(static_cast<float>(value)) : FullDecimal(value);
}

std::vector<std::string> PanelPair(Vec2 p, const PairStudy& study, bool allDigits)
{
    if (allDigits)
    {
        return {PanelNumber(p.x, study, true), PanelNumber(p.y, study, true)};
    }
    // FormatPair gives both coordinates as many decimals: "(-0.342, 0.940)".
    const std::string pair = FormatPair(p.x, p.y, "", "");
    const size_t comma = pair.find(", ");
    return {pair.substr(0, comma), pair.substr(comma + 2)};
}

std::vector<NumberRow> StaticTestNumbers(const Scene& scene, const PairStudy& study, bool allDigits,
                                         LayerMask layers)
{
    std::vector<NumberRow> rows;
    // As the sentences and the figures print them: a number here reads as the same number there.
    auto point = [&](const std::string& label, Vec2 p) { rows.push_back({label, PanelPair(p, study, allDigits)}); };
    const Manifold& m = study.manifold;
    // The textbook view shows the MTV its own test found; the contact points come from Collide's clipping.
    const bool textbook = study.Textbook();
    // The depth or the gap as the verdict's sentence gives it (the difference of the interval ends it shows); shapes
    // in contact whose depth shows as 0.00 touch without overlapping, as the verdict says: not "overlap: yes".
    const std::string amount = ShownVerdictAmount(study);
    const bool touch = m.overlap && amount == FormatNumber(0.0);
    // A depth or a gap of round-off size: they touch, as the verdict's sentence says, by that much in the numbers.
    const bool roundOff = RoundOffVerdict(study);
    rows.push_back({"overlap", {roundOff ? (m.overlap ? "yes, by round-off: they touch" : "no, by round-off: they touch")
                                : !m.overlap ? "no"
                                : touch      ? "no, they touch (in contact)"
                                             : "yes"}});
    const Vec2 normal = textbook ? study.textbookResult.normal : m.normal;
    const double depth = textbook ? study.textbookResult.depth : m.depth;
    const double gap = textbook ? study.textbookResult.gap : m.gap;
    // Beside a sweep's verdict the static test's gap is the one at t = 0, on its own axis, which need not be the
    // sweep's deciding one (fly_by: 0.50 along (0.00, 1.00) at the start, where the number line shows the sweep's
    // axis 2 and its gap 0.60): the row names both.
    const std::vector<std::string> along = PanelPair(normal, study, false);
    const std::string gapLabel = study.sweep ? "gap at t = 0 on the axis (" + along[0] + ", " + along[1] + ")"
                                             : std::string("gap on the separating axis");
    rows.push_back(m.overlap ? NumberRow{"MTV length (depth)", {allDigits ? PanelNumber(depth, study, true) : amount}}
                             : NumberRow{gapLabel, {allDigits ? PanelNumber(gap, study, true) : amount}});
    // The axis the verdict decides on, as the figure's verdict step draws it: the axis that separates, else the
    // one of the smallest push (textbook) or the best face (face tests). A sweep's steps are those of the sweep.
    if (!study.sweep)
    {
        if (textbook && !study.textbook.axes.empty())
        {
            const int last = static_cast<int>(study.textbook.axes.size()) - 1;
            const int k =
                study.textbookResult.axis >= 0 && study.textbookResult.axis <= last ? study.textbookResult.axis : last;
            const TextbookAxis& axis = study.textbook.axes[static_cast<size_t>(k)];
            point("deciding axis " + std::to_string(k + 1) + ", " + DescribeAxis(scene, study, axis.faces[0]),
                  axis.direction);
        }
        else if (!textbook && !study.trace.axes.empty())
        {
            const AxisTest& last = study.trace.axes.back();
            const int k = last.separating || last.best < 0 ? static_cast<int>(study.trace.axes.size()) - 1 : last.best;
            const AxisTest& axis = study.trace.axes[static_cast<size_t>(k)];
            point("deciding face test " + std::to_string(k + 1) + ", " + DescribeAxis(scene, study, axis.axis),
                  axis.direction);
        }
    }
    point(m.overlap ? "MTV direction (A to B)" : "normal (A to B)", normal);
    // The contact points the figure draws: a sweep's figure draws those at the time of impact (the panel lists
    // them above, as c1, c2) and none at t = 0, so the static test beside it lists none either.
    const int contacts = (layers & kLayerContacts) != 0 && !study.sweep ? m.contactCount : 0;
    for (int i = 0; i < contacts; ++i)
    {
        // In the order the figure labels them c1, c2, and satviz-query lists "contacts".
        point("contact c" + std::to_string(i + 1), m.contacts[i].point);
    }
    return rows;
}

std::string StaticHeading()
{
    return "The test's answer, as its verdict gives it (at every step):";
}

std::string SweepHeading(const Scene& scene)
{
    return SweptSpan(scene) == "the step" ? "Swept test over the step (t from 0 to 1):"
                                           : "Swept test over one second (t from 0 to 1 s), not one step of the world:";
}

std::string SweepMissLine(const Scene& scene)
{
    return "no hit during " + SweptSpan(scene) + ": no time of impact";
}

} // namespace satviz
