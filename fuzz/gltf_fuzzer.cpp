// libFuzzer target for the glTF loader: any input must load or be refused with a
// gnomon::Error. Anything else (a crash, a sanitizer report, another exception, a hang) is a
// bug. External files resolve inside an empty folder, so nothing outside is read.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gnomon/Error.h"
#include "scene/GltfLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    try {
        const gnomon::Scene scene =
            gnomon::loadGltf(bytes, "fuzz-input.gltf", "/nonexistent-fuzz-dir");
        (void)scene.validate();
    } catch (const gnomon::Error&) {
        // refused with a message: fine
    }
    return 0;
}
