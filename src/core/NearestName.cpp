// gnomon::nearestName (Error.h): the name a mistyped one was probably meant to be.
#include <algorithm>

#include "gnomon/Error.h"

namespace gnomon {

namespace {
// Edits between two words (insertions, deletions, substitutions), one row at a time.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}
}  // namespace

std::string nearestName(const std::string& word, const std::vector<std::string>& names) {
    std::string nearest;
    std::size_t best = std::max<std::size_t>(2, word.size() / 4) + 1;
    for (const std::string& name : names) {
        const std::size_t d = editDistance(word, name);
        if (d < best) {
            best = d;
            nearest = name;
        }
    }
    return nearest;
}

}  // namespace gnomon
