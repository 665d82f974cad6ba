// Little-endian binary output (STL, PLY), buffered: the byte order is written explicitly so the
// files are the same on any host.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <vector>

namespace frepkit
{

class LittleEndianBuffer
{
public:
  explicit LittleEndianBuffer(std::ostream& out)
    : out_(out)
  {
    data_.reserve(kFlushBytes + 64);
  }
  ~LittleEndianBuffer() { flush(); }
  LittleEndianBuffer(const LittleEndianBuffer&) = delete;
  LittleEndianBuffer& operator=(const LittleEndianBuffer&) = delete;

  void bytes(const void* data, std::size_t count)
  {
    const auto* p = static_cast<const unsigned char*>(data);
    data_.insert(data_.end(), p, p + count);
    maybe_flush();
  }
  void u8(std::uint8_t value) { put(value, 1); }
  void u16(std::uint16_t value) { put(value, 2); }
  void u32(std::uint32_t value) { put(value, 4); }
  void i32(std::int32_t value) { put(static_cast<std::uint32_t>(value), 4); }
  void f32(float value) { put(std::bit_cast<std::uint32_t>(value), 4); }

  void flush()
  {
    if (!data_.empty())
    {
      out_.write(
        reinterpret_cast<const char*>(data_.data()), static_cast<std::streamsize>(data_.size()));
      data_.clear();
    }
  }

private:
  static constexpr std::size_t kFlushBytes = 1 << 20;

  void put(std::uint64_t value, int count)
  {
    for (int i = 0; i < count; ++i)
    {
      data_.push_back(static_cast<unsigned char>(value >> (8 * i)));
    }
    maybe_flush();
  }
  void maybe_flush()
  {
    if (data_.size() >= kFlushBytes)
    {
      flush();
    }
  }

  std::ostream& out_;
  std::vector<unsigned char> data_;
};

} // namespace frepkit
