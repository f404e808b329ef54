// libFuzzer target for the scene file reader (docs/scene-file.md): any input must load or be
// refused with a gnomon::Error. Anything else (a crash, a sanitizer report, another
// exception, a hang) is a bug. Relative includes resolve inside a folder that does not exist,
// so only built-in scenes (and absolute paths) can be included.
#include <cstddef>
#include <cstdint>
#include <string>

#include "gnomon/Error.h"
#include "gnomon/SceneFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const gnomon::Scene scene =
            gnomon::parseSceneFile(text, "/nonexistent-fuzz-dir/fuzz-input.json");
        (void)scene.validate();
    } catch (const gnomon::Error&) {
        // refused with a message: fine
    }
    return 0;
}
