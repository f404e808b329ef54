// The shortest decimal text that reads back as the same float (0.1f as "0.1", not
// "0.10000000149011612"), for files people read and edit (scene files).
#pragma once

#include <string>

namespace gnomon {

std::string shortestText(float v);

}  // namespace gnomon
