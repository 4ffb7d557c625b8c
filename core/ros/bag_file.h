// A look at a ROS bag file's record layout without ROS: the format line, the bag header's index
// position and each chunk's compression. Tells a truncated, unindexed or non-bag file apart with
// a clear message before rosbag (which throws terse exceptions) reads it.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "core/common/status.h"

namespace sightline {

// What the records of a format 2.0 bag say.
// The largest record header the reader accepts: a header is a few named fields; anything far
// larger is a damaged length (rosbag would allocate it before reading).
inline constexpr uint32_t kMaxBagRecordHeaderBytes = 1u << 20;
// The largest chunk (uncompressed) the reader accepts: rosbag allocates a chunk's declared size
// before it decompresses it. Recorders write chunks of about 768 KiB plus one message.
inline constexpr uint32_t kMaxBagChunkBytes = 256u << 20;

struct BagFileLayout {
  int64_t file_bytes = 0;
  uint64_t index_pos = 0;                      // Where the connection and chunk index starts.
  int64_t chunks = 0;                          // Chunk records.
  std::map<std::string, int64_t> compression;  // Chunks per compression ("none", "lz4", "bz2").

  // "none", "lz4", "bz2", or "lz4 (4 of 6 chunks), none (2 of 6 chunks)" when mixed.
  std::string CompressionText() const;
};

// True for paths ending in ".bag", any case.
bool IsBagPath(const std::string& path);

// Reads the record headers of the bag at `path`, and the records inside every chunk (expanding
// bz2 and lz4 chunks): everything rosbag will follow by a length or an offset must lie where
// the bag says, before rosbag reads it. Errors name the
// path: NotFound "x.bag: no such file"; ParseError "x.bag is not a ROS bag (it does not start
// with '#ROSBAG V2.0')", "x.bag is a version 1.2 bag; only format 2.0 is read", "x.bag is
// truncated: the record at byte N needs M bytes but the file ends after K", "x.bag has no index
// (it was not closed when recorded): run 'rosbag reindex x.bag'".
StatusOr<BagFileLayout> ReadBagFileLayout(const std::string& path);

}  // namespace sightline
