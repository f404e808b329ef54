// gnomon's one exception type. Every failure the library reports (bad input, missing GL
// feature, I/O) is a gnomon::Error whose message names what failed and where, so a caller
// can print what() and stop; `kind` lets a CLI choose an exit code.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace gnomon {

enum class ErrorKind {
    InvalidInput,  // bad options, unknown scene, missing or malformed input file
    Io,            // an existing file could not be read, or output not written
    Gl,            // no usable OpenGL, a shader or framebuffer failed
};

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), mKind(kind) {}
    ErrorKind kind() const { return mKind; }

private:
    ErrorKind mKind;
};

// For "did you mean" in messages about a mistyped name (a scene, a command, a flag): the one
// of `names` fewest typing slips (a letter inserted, left out or changed) from `word`, if it
// is within max(2, letters / 4) of them, else "" (a word that near is taken for a slip, one
// further off for another name altogether). The first of equally near names wins.
std::string nearestName(const std::string& word, const std::vector<std::string>& names);

}  // namespace gnomon
