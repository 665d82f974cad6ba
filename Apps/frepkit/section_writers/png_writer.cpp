#include "png_writer.h"

#include "user_error.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <string>

namespace frepkit
{
namespace
{

using EncodePng = int (*)(std::int64_t, std::int64_t, const std::uint8_t*,
  void (*)(void*, const char*, std::size_t), void*, char*, std::size_t);

/// The encoder module next to the tool: <bin>/../lib/libfrepkit_png.so, else the loader's
/// search path.
EncodePng load_encoder()
{
  static EncodePng encode = nullptr;
  if (encode)
  {
    return encode;
  }
  std::string module = FREPKIT_PNG_MODULE;
  char executable[PATH_MAX];
  const ssize_t length = ::readlink("/proc/self/exe", executable, sizeof executable - 1);
  void* handle = nullptr;
  if (length > 0)
  {
    std::string directory(executable, static_cast<std::size_t>(length));
    directory.erase(directory.find_last_of('/'));
    handle = ::dlopen((directory + "/../lib/" + module).c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (!handle)
  {
    handle = ::dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (!handle)
  {
    throw UserError("PNG output needs " + module + ", which could not be loaded: " + ::dlerror());
  }
  encode = reinterpret_cast<EncodePng>(::dlsym(handle, "frepkit_encode_png"));
  if (!encode)
  {
    throw UserError(module + " has no frepkit_encode_png");
  }
  return encode;
}

void append_to_stream(void* context, const char* bytes, std::size_t count)
{
  static_cast<std::ostream*>(context)->write(bytes, static_cast<std::streamsize>(count));
}

} // namespace

void write_png(std::ostream& out, std::int64_t width, std::int64_t height,
  const std::vector<std::uint8_t>& rgb)
{
  char error[512] = "";
  if (load_encoder()(width, height, rgb.data(), append_to_stream, &out, error, sizeof error) != 0)
  {
    throw std::runtime_error(error);
  }
}

} // namespace frepkit
