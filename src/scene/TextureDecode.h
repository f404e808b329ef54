// Image decoding for scene loaders (stb_image, no GL): PNG, JPEG, BMP, TGA... into the
// scene model's RGBA8 Texture, with size limits so a hostile file cannot exhaust memory.
#pragma once

#include <cstddef>
#include <string>

#include "gnomon/Scene.h"

namespace gnomon {

// Largest accepted image side and encoded size.
constexpr int kMaxTextureSide = 16384;
constexpr std::size_t kMaxEncodedImageBytes = std::size_t(256) << 20;

// Decodes `size` bytes of an image file into `out` (name and sampler fields untouched).
// Returns an empty string on success, else why it failed (for the caller to name the file
// and element).
std::string decodeTexture(const unsigned char* bytes, std::size_t size, Texture& out);
// Reads and decodes an image file; throws gnomon::Error naming `path`.
Texture loadTextureFile(const std::string& path);

}  // namespace gnomon
