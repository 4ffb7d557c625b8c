#include "core/ros/bag_file.h"

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <set>

#include "core/common/text_file.h"

namespace sightline {
namespace {

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr size_t kMagicBytes = sizeof(kMagic) - 1;
constexpr uint8_t kOpMessageData = 0x02;
constexpr uint8_t kOpBagHeader = 0x03;
constexpr uint8_t kOpIndexData = 0x04;
constexpr uint8_t kOpChunk = 0x05;
constexpr uint8_t kOpChunkInfo = 0x06;
constexpr uint8_t kOpConnection = 0x07;

uint32_t ReadU32(const char* bytes) {
  uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<uint8_t>(bytes[i]);
  return value;
}

uint64_t ReadU64(const char* bytes) {
  uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | static_cast<uint8_t>(bytes[i]);
  return value;
}

// The fields of one record header: "name=value" entries, each after its 4-byte length. False
// when the entries do not tile the header exactly or one lacks its '=' (rosbag's header parser
// reads a field's declared length without checking it against the header's).
bool HeaderFields(const std::string& header, std::map<std::string, std::string>* fields) {
  size_t pos = 0;
  while (pos < header.size()) {
    if (header.size() - pos < 4) return false;
    const uint32_t len = ReadU32(header.data() + pos);
    pos += 4;
    if (len > header.size() - pos) return false;
    const std::string field = header.substr(pos, len);
    pos += len;
    const size_t eq = field.find('=');
    if (eq == std::string::npos) return false;
    (*fields)[field.substr(0, eq)] = field.substr(eq + 1);
  }
  return true;
}

Status Truncated(const std::string& path, int64_t at, int64_t needed, int64_t size) {
  return ParseError(path + " is truncated: the record at byte " + std::to_string(at) + " needs " +
                    std::to_string(needed) + " bytes but the file ends after " +
                    std::to_string(size) + " (copied or recorded only in part?)");
}

// The op code of a record's fields (0 when there is none).
uint8_t OpOf(const std::map<std::string, std::string>& fields) {
  const auto op = fields.find("op");
  return op == fields.end() || op->second.empty() ? 0 : static_cast<uint8_t>(op->second[0]);
}

// A connection record's data is itself a header (topic, type, md5sum, message_definition), which
// rosbag parses as it parses record headers.
bool ConnectionHeaderFits(const char* data, size_t size) {
  std::map<std::string, std::string> fields;
  return size <= kMaxBagRecordHeaderBytes && HeaderFields(std::string(data, size), &fields);
}

// The records inside one chunk's uncompressed bytes must tile them exactly, each header's fields
// must fit it, and a connection record's data must be a header too: rosbag reads a record at an
// index's offset in the chunk with no bound but the lengths it finds there. The offsets where a
// message data record starts go to `message_starts`. `at` names the chunk.
Status CheckChunkRecords(const std::string& bytes, const std::string& at,
                         std::set<int64_t>* message_starts) {
  const auto damaged = [&](size_t pos, const std::string& what) {
    return ParseError(at + " holds, at its byte " + std::to_string(pos) + ", " + what +
                      " (damaged bag?)");
  };
  size_t pos = 0;
  while (pos < bytes.size()) {
    if (bytes.size() - pos < 4) return damaged(pos, "a record cut short");
    const uint32_t header_len = ReadU32(bytes.data() + pos);
    if (header_len > kMaxBagRecordHeaderBytes || bytes.size() - pos - 4 < header_len + 4ull) {
      return damaged(pos, "a record header of " + std::to_string(header_len) +
                              " bytes that does not fit in the chunk");
    }
    std::map<std::string, std::string> fields;
    if (!HeaderFields(bytes.substr(pos + 4, header_len), &fields)) {
      return damaged(pos, "a record header whose fields do not fit in its " +
                              std::to_string(header_len) + " bytes");
    }
    const size_t data_at = pos + 8 + header_len;
    const uint32_t data_len = ReadU32(bytes.data() + data_at - 4);
    if (bytes.size() - data_at < data_len) {
      return damaged(pos, "a record of " + std::to_string(data_len) +
                              " data bytes that run past the chunk's end");
    }
    const uint8_t op = OpOf(fields);
    if (op == kOpConnection && !ConnectionHeaderFits(bytes.data() + data_at, data_len)) {
      return damaged(pos, "a connection header whose fields do not fit in its " +
                              std::to_string(data_len) + " bytes");
    }
    if (op == kOpMessageData) message_starts->insert(static_cast<int64_t>(pos));
    pos = data_at + data_len;
  }
  return Status::Ok();
}

// A chunk's records as rosbag will see them: the stored bytes, or their bz2 or lz4 expansion,
// which must give exactly the chunk's declared size.
StatusOr<std::string> ChunkContent(const std::string& stored, const std::string& compression,
                                   int64_t size, const std::string& at) {
  if (compression == "none") {
    if (static_cast<int64_t>(stored.size()) != size) {
      return ParseError(at + " is an uncompressed chunk of " + std::to_string(stored.size()) +
                        " bytes that says it holds " + std::to_string(size) + " (damaged bag?)");
    }
    return stored;
  }
  std::string content(static_cast<size_t>(size), '\0');
  unsigned int produced = static_cast<unsigned int>(size);
  int result = -1;
  if (compression == "bz2") {
    result = BZ2_bzBuffToBuffDecompress(content.data(), &produced, const_cast<char*>(stored.data()),
                                        static_cast<unsigned int>(stored.size()), 0, 0);
    result = result == BZ_OK ? 0 : -1;
  } else if (compression == "lz4") {
    result = roslz4_buffToBuffDecompress(const_cast<char*>(stored.data()),
                                         static_cast<unsigned int>(stored.size()), content.data(),
                                         &produced);
    result = result == ROSLZ4_OK ? 0 : -1;
  } else {
    return ParseError(at + " is compressed with '" + compression +
                      "'; the reader knows none, bz2 and lz4");
  }
  if (result != 0 || static_cast<int64_t>(produced) != size) {
    return ParseError(at + " does not expand (" + compression + ") to the " + std::to_string(size) +
                      " bytes it says it holds (damaged bag?)");
  }
  return content;
}

// Checks the format line; ParseError naming what the file starts with otherwise.
Status CheckMagic(const std::string& path, std::ifstream& in) {
  char magic[kMagicBytes] = {};
  in.read(magic, kMagicBytes);
  const std::string got(magic, static_cast<size_t>(in.gcount()));
  if (got == std::string(kMagic, kMagicBytes)) return Status::Ok();
  if (got.rfind("#ROSBAG V", 0) == 0) {
    const std::string version = got.substr(9, got.find('\n') - 9);
    return ParseError(path + " is a version " + version + " ROS bag; only format 2.0 is read");
  }
  return ParseError(path + " is not a ROS bag (it does not start with '#ROSBAG V2.0')");
}

}  // namespace

std::string BagFileLayout::CompressionText() const {
  if (compression.empty()) return "none (no chunks)";
  if (compression.size() == 1) return compression.begin()->first;
  std::string text;
  for (const auto& [name, count] : compression) {
    text += (text.empty() ? "" : ", ") + name + " (" + std::to_string(count) + " of " +
            std::to_string(chunks) + " chunks)";
  }
  return text;
}

bool IsBagPath(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".bag";
}

StatusOr<BagFileLayout> ReadBagFileLayout(const std::string& path) {
  if (!FileExists(path) && !DirectoryExists(path)) return NotFound(path + ": no such file");
  SIGHTLINE_RETURN_IF_ERROR(CheckRegularFile(path, path));
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  BagFileLayout layout;
  layout.file_bytes = static_cast<int64_t>(in.tellg());
  in.seekg(0);
  SIGHTLINE_RETURN_IF_ERROR(CheckMagic(path, in));
  bool saw_header = false;
  // rosbag seeks to index_pos, to each chunk_pos and to each message's offset in its chunk
  // without checking them: each must be where a record starts, or it reads a length from the
  // middle of one (a 1 GB allocation, a read past the chunk).
  std::set<int64_t> record_starts, chunk_starts, chunk_positions_named;
  int64_t chunk_size = -1;           // Uncompressed size of the last chunk (its "size" field).
  std::set<int64_t> chunk_messages;  // Offsets of the last chunk's message data records.
  int64_t pos = static_cast<int64_t>(kMagicBytes);
  while (pos < layout.file_bytes) {
    char len_bytes[4];
    if (layout.file_bytes - pos < 4) return Truncated(path, pos, 4, layout.file_bytes);
    in.seekg(pos);
    in.read(len_bytes, 4);
    const uint32_t header_len = ReadU32(len_bytes);
    if (header_len > kMaxBagRecordHeaderBytes) {
      return ParseError(path + ": the record at byte " + std::to_string(pos) + " has a header of " +
                        std::to_string(header_len) + " bytes (damaged bag?)");
    }
    if (layout.file_bytes - pos < 8 + static_cast<int64_t>(header_len)) {
      return Truncated(path, pos, 8 + header_len, layout.file_bytes);
    }
    std::string header(header_len, '\0');
    in.read(header.data(), header_len);
    in.read(len_bytes, 4);
    const int64_t data_len = ReadU32(len_bytes);
    const int64_t end = pos + 8 + header_len + data_len;
    if (end > layout.file_bytes) return Truncated(path, pos, end - pos, layout.file_bytes);
    std::map<std::string, std::string> fields;
    if (!HeaderFields(header, &fields)) {
      return ParseError(path + ": the record at byte " + std::to_string(pos) +
                        " has a header whose fields do not fit in its " +
                        std::to_string(header_len) + " bytes (damaged bag?)");
    }
    const uint8_t code = OpOf(fields);
    const auto field_u32 = [&](const char* name) -> int64_t {
      const auto f = fields.find(name);
      return f != fields.end() && f->second.size() == 4 ? ReadU32(f->second.data()) : -1;
    };
    const std::string at = path + ": the record at byte " + std::to_string(pos);
    record_starts.insert(pos);
    if (code == kOpBagHeader) {
      const auto index = fields.find("index_pos");
      if (index != fields.end() && index->second.size() == 8) {
        layout.index_pos = ReadU64(index->second.data());
      }
      saw_header = true;
    } else if (code == kOpChunk) {
      const auto compression = fields.find("compression");
      ++layout.chunks;
      ++layout.compression[compression == fields.end() ? "none" : compression->second];
      chunk_starts.insert(pos);
      chunk_size = field_u32("size");
      if (chunk_size < 0) return ParseError(at + " is a chunk without its size (damaged bag?)");
      if (chunk_size > static_cast<int64_t>(kMaxBagChunkBytes)) {
        return ParseError(at + " is a chunk of " + std::to_string(chunk_size) +
                          " bytes, more than the reader's limit of " +
                          std::to_string(kMaxBagChunkBytes) + " (damaged bag?)");
      }
      std::string stored(static_cast<size_t>(data_len), '\0');
      in.read(stored.data(), data_len);
      const StatusOr<std::string> content = ChunkContent(
          stored, compression == fields.end() ? "none" : compression->second, chunk_size, at);
      if (!content.ok()) return content.status();
      chunk_messages.clear();
      SIGHTLINE_RETURN_IF_ERROR(CheckChunkRecords(*content, at, &chunk_messages));
    } else if (code == kOpConnection) {
      std::string data(static_cast<size_t>(data_len), '\0');
      in.read(data.data(), data_len);
      if (!ConnectionHeaderFits(data.data(), data.size())) {
        return ParseError(at + " is a connection whose header does not fit in its " +
                          std::to_string(data_len) + " bytes (damaged bag?)");
      }
    } else if (code == kOpIndexData) {
      // Version 1: `count` entries of (time: 8 bytes, offset in the chunk: 4 bytes).
      const int64_t count = field_u32("count");
      if (count < 0 || data_len != 12 * count) {
        return ParseError(at + " is an index of " + std::to_string(count) + " messages in " +
                          std::to_string(data_len) + " bytes (damaged bag?)");
      }
      std::string entries(static_cast<size_t>(data_len), '\0');
      in.read(entries.data(), data_len);
      for (int64_t i = 0; i < count; ++i) {
        const int64_t offset = ReadU32(entries.data() + 12 * i + 8);
        if (chunk_size < 0 || chunk_messages.count(offset) == 0) {
          return ParseError(at + " indexes a message at offset " + std::to_string(offset) +
                            " of a chunk of " + std::to_string(std::max<int64_t>(chunk_size, 0)) +
                            " bytes, where no message record starts (damaged bag?)");
        }
      }
    } else if (code == kOpChunkInfo) {
      const auto chunk_pos = fields.find("chunk_pos");
      if (chunk_pos == fields.end() || chunk_pos->second.size() != 8) {
        return ParseError(at + " is a chunk summary without chunk_pos (damaged bag?)");
      }
      chunk_positions_named.insert(static_cast<int64_t>(ReadU64(chunk_pos->second.data())));
    }
    pos = end;
  }
  for (int64_t named : chunk_positions_named) {
    if (chunk_starts.count(named) == 0) {
      return ParseError(path + ": the index names a chunk at byte " + std::to_string(named) +
                        " where no chunk starts (damaged bag?)");
    }
  }
  if (!saw_header) return ParseError(path + ": no bag header record (damaged bag?)");
  if (layout.index_pos == 0) {
    return ParseError(path + " has no index (it was not closed when recorded): run 'rosbag " +
                      "reindex " + path + "'");
  }
  if (layout.index_pos >= static_cast<uint64_t>(layout.file_bytes)) {
    return Truncated(path, static_cast<int64_t>(layout.index_pos), 1, layout.file_bytes);
  }
  if (record_starts.count(static_cast<int64_t>(layout.index_pos)) == 0) {
    return ParseError(path + ": the bag header puts the index at byte " +
                      std::to_string(layout.index_pos) + ", where no record starts (damaged bag?)");
  }
  return layout;
}

}  // namespace sightline
