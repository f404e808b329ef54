// Values of the render options picked from their schema entries (kind, range, choices), for
// the tests made from the schema: each option set through the CLI or a scene file, read back
// and compared through the schema's accessors, so a new option is covered without a test
// naming it.
#pragma once

#include <cmath>
#include <string>

#include "gnomon/OptionSchema.h"

namespace gnomon::test {

// A value of `spec` that validate() accepts on its own and that differs from its value in
// `base`, as the CLI spells it: the other state, the next choice, zero where an integer
// allows it apart, else the low end of the range (the next value up when that is `base`'s),
// the middle of a real range (a quarter of it when that is `base`'s), a size one pixel
// smaller.
inline std::string otherValue(const OptionSpec& spec, const RenderOptions& base) {
    RenderOptions o = base;
    switch (spec.kind) {
        case OptionKind::Size:
            o.width = base.width > 1 ? base.width - 1 : 2;
            o.height = base.height > 1 ? base.height - 1 : 2;
            break;
        case OptionKind::Switch:
            spec.set(o, spec.get(base) != 0.0 ? 0.0 : 1.0);
            break;
        case OptionKind::Choice:
            spec.set(o, double((std::size_t(spec.get(base)) + 1) % spec.choices.size()));
            break;
        case OptionKind::Integer: {
            const double v = spec.get(base);
            if (spec.zeroAllowed && v != 0.0) {
                spec.set(o, 0.0);
            } else {
                spec.set(o, spec.min != v ? spec.min : spec.min + (spec.odd ? 2.0 : 1.0));
            }
            break;
        }
        case OptionKind::Real: {
            const double v = spec.get(base);
            if (!std::isfinite(spec.max - spec.min)) {  // unbounded: a step away
                spec.set(o, v + 1.5);
                break;
            }
            spec.set(o, spec.min + 0.5 * (spec.max - spec.min));
            if (spec.get(o) == v) spec.set(o, spec.min + 0.25 * (spec.max - spec.min));
            break;
        }
    }
    return formatOption(spec, o);
}

// Whether `a` and `b` hold the same value of `spec` (a size: both sides).
inline bool sameOption(const OptionSpec& spec, const RenderOptions& a, const RenderOptions& b) {
    if (spec.kind == OptionKind::Size) return a.width == b.width && a.height == b.height;
    return spec.get(a) == spec.get(b);
}

}  // namespace gnomon::test
