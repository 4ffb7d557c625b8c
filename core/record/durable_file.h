// Crash-safe file writing for recordings: whole files appear atomically (temporary name, fsync,
// rename) and index files grow by complete lines only, so a recording cut by a crash, a pulled
// plug or a full disk stays readable up to its last complete frame.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// A Status for a failed system call on `path`: Unavailable with "<what> <path>: <strerror>",
// and for ENOSPC / EFBIG / EDQUOT a message that says the disk (or file size limit) is full.
Status FileSystemError(const std::string& what, const std::string& path, int error_number);

// Writes `bytes` to `path` so that `path` either holds all of them or does not exist: writes
// "<path>.part", fsyncs it (when `sync`), renames it over `path`. On failure the partial file is
// removed and the status names the file.
Status WriteFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes,
                           bool sync = true);

// An index file (rgb.txt, data.csv, times.txt) that only ever holds complete lines.
//
//   AppendOnlyFile index;
//   SIGHTLINE_RETURN_IF_ERROR(index.Open(dir + "/times.txt", "# timestamp filename\n"));
//   SIGHTLINE_RETURN_IF_ERROR(index.AppendLine("0.033 000001.png"));  // durable on return
//
// Each line goes out in one write(); a short or failed write (disk full) is cut back to the
// previous line end with ftruncate, so readers never see half a line.
class AppendOnlyFile {
 public:
  AppendOnlyFile() = default;
  ~AppendOnlyFile();
  AppendOnlyFile(const AppendOnlyFile&) = delete;
  AppendOnlyFile& operator=(const AppendOnlyFile&) = delete;

  // Creates (truncates) the file and writes `header` (complete lines, may be empty).
  Status Open(const std::string& path, const std::string& header, bool sync = true);
  // Appends `line` plus '\n' and, when syncing and `durable`, fdatasyncs. On failure the file
  // is unchanged.
  Status AppendLine(const std::string& line, bool durable = true);
  void Close();

  const std::string& path() const { return path_; }
  int64_t size() const { return size_; }

 private:
  Status WriteAll(const std::string& text, bool durable);

  std::string path_;
  int fd_ = -1;
  int64_t size_ = 0;  // Bytes of complete lines.
  bool sync_ = true;
};

}  // namespace sightline
