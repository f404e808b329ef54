// gnomon's one exception type. Every failure the library reports (bad input, missing GL
// feature, I/O) is a gnomon::Error whose message names what failed and where, so a caller
// can print what() and stop; `kind` lets a CLI choose an exit code.
#pragma once

#include <stdexcept>
#include <string>

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

}  // namespace gnomon
