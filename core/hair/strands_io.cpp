#include "core/hair/strands_io.h"

#include <cstdint>
#include <vector>

#include "core/util/atomic_file.h"

namespace mq {

void writeStrandsPly(const Strands& strands, const std::string& path) {
  const size_t count = strands.strandCount(), points = size_t(strands.pointsPerStrand);
  const size_t vertices = count * points, edges = points > 1 ? count * (points - 1) : 0;
  writeFileAtomically(
      path,
      [&](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\ncomment mannequin hair strands, " << points
            << " points per strand\nelement vertex " << vertices
            << "\nproperty float x\nproperty float y\nproperty float z\nelement edge " << edges
            << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
        out.write(reinterpret_cast<const char*>(strands.points.data()), std::streamsize(vertices * 3 * sizeof(float)));
        std::vector<int32_t> pairs;
        pairs.reserve(2 * edges);
        for (size_t s = 0; s < count; ++s)
          for (size_t k = 0; k + 1 < points; ++k) {
            pairs.push_back(int32_t(s * points + k));
            pairs.push_back(int32_t(s * points + k + 1));
          }
        out.write(reinterpret_cast<const char*>(pairs.data()), std::streamsize(pairs.size() * sizeof(int32_t)));
      },
      true);
}

}  // namespace mq
