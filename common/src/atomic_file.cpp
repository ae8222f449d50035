#include "lituya/common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <streambuf>
#include <string>

namespace lituya {

namespace {

// A stream buffer on a POSIX file descriptor that keeps the errno of the first failed write.
// std::ofstream only sets failbit: by the time the caller sees it, the writer may have done
// other work that changed errno, and the reason ("No space left on device", "File too large")
// would be lost. Once a write failed, every later one fails, so a torn file is never taken for
// a whole one.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  DescriptorBuffer(const DescriptorBuffer&) = delete;
  DescriptorBuffer& operator=(const DescriptorBuffer&) = delete;

  // 0 while every write succeeded, else the errno of the first failure.
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }

  // Blocks larger than the buffer (VTU arrays) go to the file directly, without a copy.
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n < static_cast<std::streamsize>(buffer_.size())) return std::streambuf::xsputn(s, n);
    if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
    return n;
  }

  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return write_all(buffer_.data(), n);
  }

  bool write_all(const char* s, std::size_t n) {
    if (error_ != 0) return false;
    while (n > 0) {
      const ssize_t written = ::write(fd_, s, n);
      if (written < 0) {
        if (errno == EINTR) continue;  // a signal (SIGINT asks for a clean stop) is no error
        error_ = errno;
        return false;
      }
      s += written;
      n -= static_cast<std::size_t>(written);
    }
    return true;
  }

  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> buffer_{};
};

// `temporary`: the file this write created, removed so that a failed write leaves nothing
// behind but the old file; empty when creating it failed (what is there is not ours).
[[noreturn]] void fail(const std::filesystem::path& file, const std::filesystem::path& temporary,
                       const std::string& what, int error) {
  std::error_code ignore;
  if (!temporary.empty()) std::filesystem::remove(temporary, ignore);
  throw WriteError("cannot write " + file.string() + ": " + what + ": " + std::strerror(error) +
                   " (" +
                   (std::filesystem::exists(file, ignore) ? "the previous file is kept"
                                                          : "no file was written") +
                   ")");
}

int open_for_writing(const std::filesystem::path& temporary) {
  return ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
}

}  // namespace

std::filesystem::path temporary_file_for(const std::filesystem::path& file) {
  return std::filesystem::path(file).concat(".tmp");
}

namespace detail {

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write,
                           const OpenTemporary& open) {
  const std::filesystem::path temporary = temporary_file_for(file);
  // errno is read at once after each failing call: anything done before could change it.
  const int fd = open(temporary);
  if (fd < 0) {
    const int error = errno;
    fail(file, {}, "cannot create " + temporary.string(), error);
  }
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  try {
    write(out);
  } catch (...) {
    ::close(fd);
    std::error_code ignore;
    std::filesystem::remove(temporary, ignore);
    throw;
  }
  // The buffer is drained directly: ostream::flush does nothing on a stream whose failbit a
  // formatted insertion set (inserting an empty streambuf does), and the bytes would be lost.
  // Every byte goes through the buffer, so its error is the whole story of the write.
  buffer.pubsync();
  if (buffer.error() != 0) {
    ::close(fd);
    fail(file, temporary, "error while writing " + temporary.string(), buffer.error());
  }
  // Some file systems (NFS, quotas) report a full disk only when the file is closed.
  if (::close(fd) != 0) {
    const int error = errno;
    fail(file, temporary, "error while closing " + temporary.string(), error);
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    fail(file, temporary, "cannot rename " + temporary.string() + " to it", error);
  }
}

}  // namespace detail

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write) {
  detail::write_file_atomically(file, write, open_for_writing);
}

void write_file_atomically(const std::filesystem::path& file, std::string_view content) {
  write_file_atomically(file, [content](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

void copy_file_atomically(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::ifstream in(from, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw WriteError("cannot copy " + from.string() + " to " + to.string() + ": " +
                     std::strerror(error));
  }
  write_file_atomically(to, [&](std::ostream& out) {
    if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
  });
}

}  // namespace lituya
