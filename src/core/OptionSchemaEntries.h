// Shared by the files that declare the render options (OptionSchema.cpp: the frame's
// options and the schema itself; ShadowOptionSchema.cpp: the shadow technique's): how an
// entry reads and writes its member, and the technique groups' entries.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "gnomon/OptionSchema.h"

namespace gnomon::schema {

// The names of an enum's values in its order, as toString spells them.
template <typename E>
inline std::vector<std::string> namesOf() {
    std::vector<std::string> out;
    for (int i = 0; i < 64; ++i) {
        const std::string name = toString(E(i));
        if (name == "?") break;
        out.push_back(name);
    }
    return out;
}

// Accessors for a member reached by `FIELD` (an expression of `o`), as numbers.
#define NUMBER(FIELD, TYPE)                                                    \
    .get = [](const RenderOptions& o) { return double(o.FIELD); },             \
    .set = [](RenderOptions& o, double v) { o.FIELD = static_cast<TYPE>(v); }, \
    .field = [](const RenderOptions& o) -> const void* { return &o.FIELD; }
#define ENUM(FIELD, TYPE)                                               \
    .get = [](const RenderOptions& o) { return double(int(o.FIELD)); }, \
    .set = [](RenderOptions& o, double v) { o.FIELD = TYPE(int(v)); },  \
    .field = [](const RenderOptions& o) -> const void* { return &o.FIELD; }

inline constexpr double kHuge = std::numeric_limits<double>::max();  // "no bound"

// The shadow technique's groups, in help order (ShadowOptionSchema.cpp).
void addShadowMaps(std::vector<OptionSpec>& s);
void addTolerances(std::vector<OptionSpec>& s);
void addFiltering(std::vector<OptionSpec>& s);
void addCascades(std::vector<OptionSpec>& s);

}  // namespace gnomon::schema
