#include "scene/TextureDecode.h"

#include <climits>
#include <fstream>
#include <memory>
#include <vector>

#include <stb/stb_image.h>

#include "gnomon/Error.h"

namespace gnomon {

std::string decodeTexture(const unsigned char* bytes, std::size_t size, Texture& out) {
    if (size == 0) return "the image is empty";
    if (size > kMaxEncodedImageBytes || size > std::size_t(INT_MAX)) {
        return "the image is " + std::to_string(size >> 20) + " MiB, more than the " +
               std::to_string(kMaxEncodedImageBytes >> 20) + " MiB allowed";
    }
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_memory(bytes, int(size), &w, &h, &n)) {
        return std::string("the image cannot be decoded (") + stbi_failure_reason() + ")";
    }
    if (w <= 0 || h <= 0 || w > kMaxTextureSide || h > kMaxTextureSide) {
        return "the image is " + std::to_string(w) + "x" + std::to_string(h) + ", outside 1.." +
               std::to_string(kMaxTextureSide) + " per side";
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes, int(size), &w, &h, &n, 4), stbi_image_free);
    if (!data) return std::string("the image cannot be decoded (") + stbi_failure_reason() + ")";
    out.width = w;
    out.height = h;
    out.rgba.assign(data.get(), data.get() + std::size_t(w) * std::size_t(h) * 4);
    return {};
}

Texture loadTextureFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::Io, "cannot read image '" + path + "'");
    in.seekg(0, std::ios::end);
    const std::streamoff length = in.tellg();
    in.seekg(0);
    if (length < 0 || std::size_t(length) > kMaxEncodedImageBytes) {
        throw Error(ErrorKind::InvalidInput, "image '" + path + "' is larger than the " +
                                                 std::to_string(kMaxEncodedImageBytes >> 20) +
                                                 " MiB allowed");
    }
    std::vector<unsigned char> bytes(static_cast<std::size_t>(length));
    in.read(reinterpret_cast<char*>(bytes.data()), length);
    if (!in) throw Error(ErrorKind::Io, "cannot read image '" + path + "'");
    Texture t;
    t.name = path;
    if (std::string why = decodeTexture(bytes.data(), bytes.size(), t); !why.empty()) {
        throw Error(ErrorKind::InvalidInput, "image '" + path + "': " + why);
    }
    return t;
}

}  // namespace gnomon
