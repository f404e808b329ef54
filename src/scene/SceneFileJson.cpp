// The strict JSON layer of scene files: JSON paths for messages, and the parse that checks
// syntax, duplicate keys and nesting before nlohmann builds the document.
#include "scene/SceneFileJson.h"

#include <cctype>
#include <set>

namespace gnomon::scenefile {
namespace {

bool plainKey(const std::string& k) {
    return !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    });
}

// A first pass over the text without building anything (nlohmann's callback parser is
// quadratic in an object's size): syntax, duplicate keys, nesting depth, key order.
class Checker {
public:
    Checker(const Reader& r, Parsed& out) : mReader(r), mOut(out) {}
    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(Json::number_integer_t) { return value(); }
    bool number_unsigned(Json::number_unsigned_t) { return value(); }
    bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
    bool string(Json::string_t&) { return value(); }
    bool binary(Json::binary_t&) { return value(); }
    bool start_object(std::size_t) { return start(false); }
    bool start_array(std::size_t) { return start(true); }
    bool end_object() { return end(); }
    bool end_array() { return end(); }
    bool key(Json::string_t& k) {
        Frame& f = mFrames.back();
        f.key = k;
        if (!f.keys.insert(k).second)
            mReader.fail(pathOf(mFrames.size() - 1), "duplicate key " + Json(k).dump());
        if (mFrames.size() == 2 && (mFrames[0].key == "materials" || mFrames[0].key == "meshes"))
            mOut.order[mFrames[0].key].push_back(k);
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        std::string what = e.what();
        if (auto at = what.find("] "); at != std::string::npos) what = what.substr(at + 2);
        mReader.fail("", "not valid JSON: " + what);
    }

private:
    struct Frame {
        bool array = false;
        std::size_t count = 0;  // arrays: elements started so far
        std::string key;        // objects: the key being read
        std::set<std::string> keys;
    };
    std::string pathOf(std::size_t n) const {
        std::string p;
        for (std::size_t i = 0; i < n; ++i)
            p = mFrames[i].array ? element(p, mFrames[i].count - 1) : member(p, mFrames[i].key);
        return p;
    }
    bool value() {
        if (!mFrames.empty() && mFrames.back().array) ++mFrames.back().count;
        return true;
    }
    bool start(bool array) {
        value();
        if (mFrames.size() >= kMaxNesting) {
            mReader.fail(pathOf(mFrames.size()), "arrays and objects nest deeper than " +
                                                     std::to_string(kMaxNesting) + " levels");
        }
        mFrames.push_back(Frame{array, 0, {}, {}});
        return true;
    }
    bool end() {
        if (!mFrames.empty()) mFrames.pop_back();
        return true;
    }

    const Reader& mReader;
    Parsed& mOut;
    std::vector<Frame> mFrames;
};

}  // namespace

std::string member(const std::string& path, const std::string& key) {
    if (plainKey(key)) return path.empty() ? key : path + "." + key;
    return path + "[" + Json(key).dump() + "]";
}

std::string element(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

std::string preview(const Json& v) {
    switch (v.type()) {
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "an array";
        case Json::value_t::null:
            return "null";
        default:
            break;
    }
    std::string s = v.dump();
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    return s;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const std::string& s : items)
        out += (out.empty() ? "" : separator) + s;
    return out;
}

Parsed parseJson(const std::string& text, const Reader& r) {
    Parsed out;
    Checker checker(r, out);
    if (!Json::sax_parse(text, &checker, Json::input_format_t::json, true, true))
        r.fail("", "not valid JSON");
    out.doc = Json::parse(text, nullptr, true, true);
    return out;
}

}  // namespace gnomon::scenefile
