# The web build's third-party code (EMSCRIPTEN; `make web`, docs/web.md), under the target
# names the native build gets from find_package, so src/CMakeLists.txt links the same names:
# - header-only libraries from Debian's packages: /usr/include itself cannot be an include
#   folder here (glibc's headers would shadow Emscripten's), so glm, nlohmann, stb and
#   tiny_gltf.h are linked into a staging folder of the build tree;
# - the code Debian builds into shared libraries (stb, tinygltf) compiled from those headers;
# - meshoptimizer and Dear ImGui compiled from Debian's source packages, which
#   scripts/web-deps.sh unpacks (GNOMON_WEB_SRC).
# gnomon reports failures as exceptions: wasm's own exception handling, in every object.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)

set(GNOMON_WEB_SRC "${PROJECT_SOURCE_DIR}/build/web-src" CACHE PATH
    "Debian's source packages of Dear ImGui and meshoptimizer, unpacked by scripts/web-deps.sh")
foreach(package imgui meshoptimizer)
    if(NOT IS_DIRECTORY "${GNOMON_WEB_SRC}/${package}")
        message(FATAL_ERROR "${GNOMON_WEB_SRC}/${package} is missing: run scripts/web-deps.sh")
    endif()
endforeach()

set(staging "${CMAKE_BINARY_DIR}/staging-include")
file(MAKE_DIRECTORY "${staging}")
foreach(header glm nlohmann stb tiny_gltf.h CLI)
    if(NOT EXISTS "/usr/include/${header}")
        message(FATAL_ERROR "/usr/include/${header} is missing: run scripts/web-deps.sh")
    endif()
    file(CREATE_LINK "/usr/include/${header}" "${staging}/${header}" SYMBOLIC)
endforeach()

add_library(gnomon_web_headers INTERFACE)
# stb's own folder too: tinygltf includes <stb_image.h>.
target_include_directories(gnomon_web_headers SYSTEM INTERFACE "${staging}" "${staging}/stb")
add_library(glm::glm ALIAS gnomon_web_headers)
add_library(nlohmann_json::nlohmann_json ALIAS gnomon_web_headers)
add_library(CLI11::CLI11 ALIAS gnomon_web_headers)

# Third-party code is compiled as its authors wrote it: no warnings of ours.
set(generated "${CMAKE_BINARY_DIR}/third-party")
file(WRITE "${generated}/stb.c" "#define STB_IMAGE_IMPLEMENTATION\n#include <stb/stb_image.h>\n"
    "#define STB_IMAGE_WRITE_IMPLEMENTATION\n#include <stb/stb_image_write.h>\n")
add_library(gnomon_web_stb STATIC "${generated}/stb.c")
target_link_libraries(gnomon_web_stb PUBLIC gnomon_web_headers)
add_library(PkgConfig::stb ALIAS gnomon_web_stb)

# Debian's README.Debian for tinygltf: one file with TINYGLTF_IMPLEMENTATION.
file(WRITE "${generated}/tinygltf.cpp" "#define TINYGLTF_IMPLEMENTATION\n#include <tiny_gltf.h>\n")
add_library(gnomon_web_tinygltf STATIC "${generated}/tinygltf.cpp")
target_link_libraries(gnomon_web_tinygltf PUBLIC gnomon_web_stb)
add_library(TinyGLTF::TinyGLTF ALIAS gnomon_web_tinygltf)

file(GLOB meshopt_sources CONFIGURE_DEPENDS "${GNOMON_WEB_SRC}/meshoptimizer/src/*.cpp")
add_library(gnomon_web_meshoptimizer STATIC ${meshopt_sources})
target_include_directories(gnomon_web_meshoptimizer SYSTEM PUBLIC
    "${GNOMON_WEB_SRC}/meshoptimizer/src")
add_library(meshoptimizer::meshoptimizer ALIAS gnomon_web_meshoptimizer)

# Dear ImGui with the backends the viewer uses (GLFW, OpenGL 3 as GLES 3 / WebGL2), for the
# viewer's port to the page.
set(imgui "${GNOMON_WEB_SRC}/imgui")
add_library(gnomon_web_imgui STATIC
    "${imgui}/imgui.cpp" "${imgui}/imgui_draw.cpp" "${imgui}/imgui_tables.cpp"
    "${imgui}/imgui_widgets.cpp" "${imgui}/backends/imgui_impl_glfw.cpp"
    "${imgui}/backends/imgui_impl_opengl3.cpp")
target_include_directories(gnomon_web_imgui SYSTEM PUBLIC "${imgui}" "${imgui}/backends")
target_link_options(gnomon_web_imgui INTERFACE -sUSE_GLFW=3 -sMAX_WEBGL_VERSION=2)
add_library(PkgConfig::imgui ALIAS gnomon_web_imgui)
