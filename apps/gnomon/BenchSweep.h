// `gnomon bench --sweep`: the values a sweep runs over and the scene and options of each.
#pragma once

#include <string>
#include <vector>

#include "BenchCommand.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {

// The values --sweep runs over: --values, else the parameter's defaults (none without
// --sweep). Throws gnomon::Error for an unknown parameter or --values without --sweep.
std::vector<std::string> sweepValues(const BenchArgs& args);
// `scene` and `options` for `value` of `param`, made from the base ones. Throws
// gnomon::Error naming a value out of range.
void applySweep(const std::string& param, const std::string& value, const Scene& base,
                const RenderOptions& baseOptions, Scene& scene, RenderOptions& options);

}  // namespace gnomon::cli
