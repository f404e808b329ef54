// Move-only ownership of one OpenGL name (Magnum-style): empty by default, release() hands
// the name over, the destructor deletes only a live name. Each wrapper type below supplies
// its delete call; creation goes through DSA (glCreate*) so objects exist before binding.
#pragma once

#include "gl/Gl.h"

#include <string>
#include <utility>

namespace gnomon::gl {

void setLabel(GLenum identifier, GLuint name, const std::string& label);

template <typename Deleter>
class Object {
public:
    Object() = default;
    explicit Object(GLuint name) : mName(name) {}
    ~Object() {
        if (mName != 0) Deleter::destroy(mName);
    }
    Object(Object&& other) noexcept : mName(std::exchange(other.mName, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            if (mName != 0) Deleter::destroy(mName);
            mName = std::exchange(other.mName, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint id() const { return mName; }
    GLuint release() { return std::exchange(mName, 0); }
    explicit operator bool() const { return mName != 0; }

private:
    GLuint mName = 0;
};

}  // namespace gnomon::gl
