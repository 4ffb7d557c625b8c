#include "core/record/durable_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace sightline {

Status FileSystemError(const std::string& what, const std::string& path, int error_number) {
  std::string message = what + " " + path + ": " + std::strerror(error_number);
  if (error_number == ENOSPC || error_number == EDQUOT) {
    message += " (the disk is full; the recording is valid up to the last complete frame)";
  } else if (error_number == EFBIG) {
    message +=
        " (the file size limit is reached; the recording is valid up to the last "
        "complete frame)";
  }
  return Unavailable(message);
}

namespace {

// Writes all of `data` to `fd`; returns 0 or the errno of the failure.
int WriteFully(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return ENOSPC;
    p += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

Status WriteFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes, bool sync) {
  const std::string part = path + ".part";
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return FileSystemError("cannot create", part, errno);
  int error = WriteFully(fd, bytes.data(), bytes.size());
  if (error == 0 && sync && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(part.c_str());
    return FileSystemError("cannot write", path, error);
  }
  if (std::rename(part.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(part.c_str());
    return FileSystemError("cannot rename to", path, error);
  }
  return Status::Ok();
}

AppendOnlyFile::~AppendOnlyFile() { Close(); }

Status AppendOnlyFile::Open(const std::string& path, const std::string& header, bool sync) {
  Close();
  path_ = path;
  sync_ = sync;
  size_ = 0;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) return FileSystemError("cannot create", path, errno);
  return header.empty() ? Status::Ok() : WriteAll(header, true);
}

Status AppendOnlyFile::AppendLine(const std::string& line, bool durable) {
  if (fd_ < 0) return FailedPrecondition(path_ + " is not open");
  return WriteAll(line + "\n", durable);
}

Status AppendOnlyFile::WriteAll(const std::string& text, bool durable) {
  int error = WriteFully(fd_, text.data(), text.size());
  if (error == 0 && sync_ && durable && ::fdatasync(fd_) != 0) error = errno;
  if (error != 0) {
    // Cut a partial line back so that readers see only complete ones.
    if (::ftruncate(fd_, size_) != 0) {
      // Nothing more can be done; the message below still names the file.
    }
    return FileSystemError("cannot append to", path_, error);
  }
  size_ += static_cast<int64_t>(text.size());
  return Status::Ok();
}

void AppendOnlyFile::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace sightline
