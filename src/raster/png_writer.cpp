// Atomic PNG writing; see png_writer.h.
#include "raster/png_writer.h"

#include <stb_image_write.h>  // implementation lives in libstb.so
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace vlit::raster {

namespace {

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

struct WriteState {
  std::FILE* file;
  bool ok;
};

void write_chunk(void* context, void* data, int size) {
  auto* state = static_cast<WriteState*>(context);
  if (state->ok && std::fwrite(data, 1, size_t(size), state->file) != size_t(size)) state->ok = false;
}

}  // namespace

bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
               std::string* error) {
  if (width <= 0 || height <= 0) return fail(error, path + ": image size must be positive");
  // stb_image_write sizes its buffers with int: (3 width + 1) height bytes must fit.
  if ((size_t(width) * 3 + 1) * size_t(height) > size_t(std::numeric_limits<int>::max()))
    return fail(error, path + ": image too large for the PNG encoder (over 2 GiB of pixels)");
  if (rgb8.size() != size_t(width) * size_t(height) * 3)
    return fail(error, path + ": pixel buffer size does not match width x height x 3");

  std::string temp = path + ".tmp.XXXXXX";
  const int fd = mkstemp(temp.data());
  if (fd < 0) return fail(error, path + ": cannot create temporary file: " + std::strerror(errno));
  fchmod(fd, 0644);
  std::FILE* file = fdopen(fd, "wb");
  if (!file) {
    const int e = errno;
    close(fd);
    unlink(temp.c_str());
    return fail(error, path + ": cannot open temporary file: " + std::strerror(e));
  }
  WriteState state{file, true};
  const int encoded = stbi_write_png_to_func(write_chunk, &state, width, height, 3, rgb8.data(), width * 3);
  bool ok = encoded != 0 && state.ok && std::fflush(file) == 0 && fsync(fileno(file)) == 0;
  const int e = errno;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) {
    unlink(temp.c_str());
    return fail(error, path + ": writing failed" + (encoded ? std::string(": ") + std::strerror(e) : " (encoder)"));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int re = errno;
    unlink(temp.c_str());
    return fail(error, path + ": cannot rename temporary file into place: " + std::strerror(re));
  }
  return true;
}

}  // namespace vlit::raster
