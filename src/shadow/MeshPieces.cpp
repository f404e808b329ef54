#include "shadow/MeshPieces.h"

#include <algorithm>

#include <meshoptimizer.h>

namespace gnomon::shadow {

namespace {

// Sorts indices [first, first + count) along the curve and appends their pieces.
void cutGroup(const std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& indices,
              std::uint32_t first, std::uint32_t count, bool closed,
              std::vector<MeshPiece>& pieces) {
    if (count == 0) return;
    std::vector<std::uint32_t> sorted(count);
    meshopt_spatialSortTriangles(sorted.data(), indices.data() + first, count, &positions[0].x,
                                 positions.size(), sizeof(glm::vec3));
    std::copy(sorted.begin(), sorted.end(), indices.begin() + first);
    for (std::uint32_t at = 0; at < count; at += 3 * kPieceTriangles) {
        MeshPiece piece;
        piece.firstIndex = first + at;
        piece.indexCount = std::min(3 * kPieceTriangles, count - at);
        piece.closed = closed;
        for (std::uint32_t i = 0; i < piece.indexCount; ++i)
            piece.bounds.extend(positions[indices[piece.firstIndex + i]]);
        pieces.push_back(piece);
    }
}

}  // namespace

std::vector<MeshPiece> cutIntoPieces(const std::vector<glm::vec3>& positions,
                                     std::vector<std::uint32_t>& indices,
                                     std::size_t closedIndices) {
    std::vector<MeshPiece> pieces;
    const auto count = std::uint32_t(indices.size());
    const auto closed = std::uint32_t(std::min(closedIndices, indices.size()));
    if (count < 3 * 2 * kPieceTriangles || positions.empty()) {
        MeshPiece whole{0, count, false, {}};
        for (const glm::vec3& p : positions)
            whole.bounds.extend(p);
        pieces.push_back(whole);
        return pieces;
    }
    cutGroup(positions, indices, 0, closed, true, pieces);
    cutGroup(positions, indices, closed, count - closed, false, pieces);
    return pieces;
}

}  // namespace gnomon::shadow
