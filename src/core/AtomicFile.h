// Write-then-rename: output goes to a temporary file beside the target, which is renamed
// into place only when everything was written, so readers never see half a file.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

namespace gnomon {

// Calls `write` with an open FILE*; throws gnomon::Error (kind Io) naming `path` on failure.
void writeFileAtomically(const std::string& path, const std::function<void(std::FILE*)>& write);

}  // namespace gnomon
