#include "truth/Flicker.h"

#include "gnomon/Error.h"

namespace gnomon::truth {

namespace {
bool shadowed(const Reference& r, std::size_t cell, bool soft) {
    return (soft ? r.soft[cell] : r.hard[cell]) < 0.5f;
}
}  // namespace

FlickerCount countFlicker(const Reference& referenceBefore, const std::vector<float>& before,
                          const Reference& referenceAfter, const std::vector<float>& after,
                          bool soft) {
    const Reference& a = referenceBefore;
    const Reference& b = referenceAfter;
    if (a.width != b.width || a.height != b.height || a.lights != b.lights ||
        before.size() != a.applies.size() || after.size() != b.applies.size()) {
        throw Error(ErrorKind::InvalidInput, "flicker: the two frames differ in size or lights");
    }
    FlickerCount count;
    count.map.assign(std::size_t(b.width) * std::size_t(b.height), 0);
    const std::size_t lights = std::size_t(b.lights);
    for (std::size_t p = 0; p < count.map.size(); ++p) {
        for (std::size_t l = 0; l < lights; ++l) {
            const std::size_t cell = p * lights + l;
            if (!a.applies[cell] || !b.applies[cell]) continue;
            ++count.compared;
            const bool truthChanged = shadowed(a, cell, soft) != shadowed(b, cell, soft);
            const bool renderChanged = (before[cell] < 0.5f) != (after[cell] < 0.5f);
            count.truthChanged += truthChanged;
            if (renderChanged && !truthChanged) {
                ++count.flickered;
                count.map[p] = 1;
            }
        }
    }
    return count;
}

}  // namespace gnomon::truth
