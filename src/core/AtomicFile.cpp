#include "core/AtomicFile.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {

void writeFileAtomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // Built by appending: GCC 12 warns (-Wrestrict, a known false positive) on a + chain here.
    std::string name = ".";
    name.append(target.filename().string()).append(".XXXXXX");
    std::string tmpl = (dir / name).string();
    int fd = mkstemp(tmpl.data());
    if (fd < 0) {
        throw Error(ErrorKind::Io, "cannot write '" + path + "': " + std::strerror(errno) +
                                       " (in folder '" + dir.string() + "')");
    }
    std::FILE* f = fdopen(fd, "wb");
    if (!f) {
        ::close(fd);
        ::unlink(tmpl.c_str());
        throw Error(ErrorKind::Io, "cannot write '" + path + "': " + std::strerror(errno));
    }
    try {
        write(f);
    } catch (...) {
        std::fclose(f);
        ::unlink(tmpl.c_str());
        throw;
    }
    const bool ok = std::fflush(f) == 0 && !std::ferror(f);
    const int closeResult = std::fclose(f);
    if (!ok || closeResult != 0) {
        ::unlink(tmpl.c_str());
        throw Error(ErrorKind::Io, "cannot write '" + path + "': " + std::strerror(errno));
    }
    // mkstemp creates 0600; give the file the usual permissions before it appears.
    ::chmod(tmpl.c_str(), 0644);
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        ::unlink(tmpl.c_str());
        throw Error(ErrorKind::Io, "cannot write '" + path + "': " + reason);
    }
}

void writeTextFile(const std::string& path, const std::string& text) {
    writeFileAtomically(path, [&](std::FILE* f) {
        if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) {
            throw Error(ErrorKind::Io, "cannot write '" + path + "': " + std::strerror(errno));
        }
    });
}

}  // namespace gnomon
