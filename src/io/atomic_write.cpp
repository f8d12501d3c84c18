#include "io/atomic_write.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/input_error.h"

namespace vlit {
namespace {

constexpr std::string_view kTemporaryInfix = ".vlit-tmp-";
constexpr std::size_t kTemporaryRandomChars = 6;  // mkstemp's XXXXXX

// The temporary being written, for remove_temporary_in_progress. `g_claimed` makes one write the
// owner of the buffer; `g_pending` says the buffer holds a complete path.
char g_pending_path[4096];
std::atomic<bool> g_claimed{false};
std::atomic<bool> g_pending{false};

// Tracks a temporary while it exists; a no-op if another write already holds the buffer.
class PendingTemporary {
 public:
  explicit PendingTemporary(const std::string& path) {
    if (path.size() >= sizeof g_pending_path || g_claimed.exchange(true)) return;
    owner_ = true;
    std::memcpy(g_pending_path, path.c_str(), path.size() + 1);
    g_pending.store(true);
  }
  ~PendingTemporary() {
    if (!owner_) return;
    g_pending.store(false);
    g_claimed.store(false);
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  bool owner_ = false;
};

}  // namespace

std::string output_of_temporary(const std::string& path) {
  const std::filesystem::path p(path);
  const std::string name = p.filename().string();
  const std::size_t infix = name.rfind(kTemporaryInfix);
  if (name.size() < 2 || name[0] != '.' || infix == std::string::npos || infix < 2 ||
      name.size() != infix + kTemporaryInfix.size() + kTemporaryRandomChars)
    return {};
  return (p.parent_path() / name.substr(1, infix - 1)).string();
}

void remove_temporary_in_progress() noexcept {
  if (g_pending.load()) ::unlink(g_pending_path);
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(path, "output directory does not exist: " + dir.string());
  // Appended piece by piece: GCC 12 gives a false -Wrestrict warning for "." + std::string&&.
  std::string hidden = ".";
  hidden += target.filename().string();
  hidden += kTemporaryInfix;
  hidden += "XXXXXX";
  const std::string tmpl = (dir / hidden).string();
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) throw InputError(path, std::string("cannot create a temporary file: ") + std::strerror(errno));
  const std::string tmp_path(name.data());
  const PendingTemporary pending(tmp_path);
  auto fail = [&](const std::string& what) {
    const int saved = errno;
    ::close(fd);
    ::unlink(tmp_path.c_str());
    throw InputError(path, what + ": " + std::strerror(saved));
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fchmod(fd, 0644) != 0) fail("cannot set permissions");
  if (::fsync(fd) != 0) fail("cannot flush");
  if (::close(fd) != 0) {
    ::unlink(tmp_path.c_str());
    throw InputError(path, std::string("cannot close: ") + std::strerror(errno));
  }
  if (std::rename(tmp_path.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(tmp_path.c_str());
    throw InputError(path, std::string("cannot rename into place: ") + std::strerror(saved));
  }
}

}  // namespace vlit
