// The files one command writes, all or none: an output folder is made at once (an unwritable
// place fails before the work), each file is written through a temporary file and renamed
// (AtomicFile), and unless keep() is called, the destructor (a failure or an interrupt on the
// way) removes the files written so far and the folder when it made it.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "gnomon/Error.h"

namespace gnomon::cli {

class OutputSet {
public:
    // Files anywhere (add()), no folder.
    OutputSet() = default;
    // With `folder` for file(); `flag` names the folder's option in messages ("--out-dir").
    OutputSet(std::string folder, const std::string& flag) : mFolder(std::move(folder)) {
        std::error_code ec;
        mMade = !std::filesystem::exists(mFolder, ec);
        std::filesystem::create_directories(mFolder, ec);
        if (ec || !std::filesystem::is_directory(mFolder, ec)) {
            throw Error(ErrorKind::Io, flag + ": cannot create folder '" + mFolder +
                                           "': " + (ec ? ec.message() : "a file is in the way"));
        }
    }
    ~OutputSet() {
        if (mKept) return;
        std::error_code ec;
        for (const std::string& path : mWritten)
            std::filesystem::remove(path, ec);
        if (mMade) std::filesystem::remove(mFolder, ec);  // only when empty
    }
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // The path of `name` in the folder, recorded as written (call before writing it).
    std::string file(const std::string& name) { return add(mFolder + "/" + name); }
    // `path`, anywhere, recorded as written (call before writing it).
    const std::string& add(const std::string& path) {
        mWritten.push_back(path);
        return mWritten.back();
    }
    void keep() { mKept = true; }

private:
    std::string mFolder;
    std::vector<std::string> mWritten;
    bool mMade = false;
    bool mKept = false;
};

}  // namespace gnomon::cli
