#include "io/joint_state_cdr.h"

#include <cstring>
#include <type_traits>

namespace massprops::io_internal {

namespace {

// Reads XCDR1 primitives from a buffer after its encapsulation header; the first failure sticks.
class CdrCursor {
 public:
  CdrCursor(const std::uint8_t* data, std::size_t size, bool little_endian)
      : data_(data), size_(size), little_(little_endian) {}

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }

  template <typename T>
  T Primitive(const char* what) {
    T value{};
    if (!Align(sizeof(T), what) || !Need(sizeof(T), what)) return value;
    // The value's bits as an unsigned integer of its size, whatever the host's byte order.
    using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
    static_assert(sizeof(T) == sizeof(Bits), "4- and 8-byte primitives only");
    Bits bits = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      const Bits byte = data_[at_ + (little_ ? i : sizeof(T) - 1 - i)];
      bits = static_cast<Bits>(bits | (byte << (8 * i)));
    }
    std::memcpy(&value, &bits, sizeof(T));
    at_ += sizeof(T);
    return value;
  }

  std::string String(const char* what) {
    const std::uint32_t length = Primitive<std::uint32_t>(what);
    if (!ok() || !Need(length, what)) return "";
    std::size_t text = length;
    while (text > 0 && data_[at_ + text - 1] == 0) --text;  // the NUL (and any padding NULs)
    std::string s(reinterpret_cast<const char*>(data_ + at_), text);
    at_ += length;
    return s;
  }

  std::vector<std::string> Strings(const char* what) {
    const std::uint32_t count = Primitive<std::uint32_t>(what);
    std::vector<std::string> out;
    // Each string takes at least its 4-byte length: a count beyond that is a broken message.
    if (!ok() || !Need(std::size_t{count} * 4, what)) return out;
    for (std::uint32_t i = 0; i < count && ok(); ++i) out.push_back(String(what));
    return out;
  }

  std::vector<double> Doubles(const char* what) {
    const std::uint32_t count = Primitive<std::uint32_t>(what);
    std::vector<double> out;
    if (!ok() || count == 0) return out;  // no alignment after an empty sequence's count
    if (!Align(8, what) || !Need(std::size_t{count} * 8, what)) return out;
    out.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) out.push_back(Primitive<double>(what));
    return out;
  }

 private:
  bool Align(std::size_t n, const char* what) {
    const std::size_t padded = (at_ + n - 1) / n * n;
    if (padded > size_) return Fail(what);
    at_ = padded;
    return true;
  }
  bool Need(std::size_t n, const char* what) { return n <= size_ - at_ ? true : Fail(what); }
  bool Fail(const char* what) {
    if (error_.empty()) {
      error_ = std::string("truncated: the message ends inside its '") + what + "' (" +
               std::to_string(size_) + " bytes after the encapsulation header)";
    }
    at_ = size_;
    return false;
  }

  const std::uint8_t* data_;
  std::size_t size_;
  bool little_;
  std::size_t at_ = 0;
  std::string error_;
};

}  // namespace

std::optional<JointStateMessage> ParseJointStateCdr(const std::uint8_t* data, std::size_t size,
                                                    std::string* error) {
  if (size < 4) {
    *error = "truncated: " + std::to_string(size) + " bytes, not even the CDR encapsulation header";
    return std::nullopt;
  }
  if (data[0] != 0 || data[1] > 1) {
    *error = "CDR encapsulation " + std::to_string(data[0]) + "," + std::to_string(data[1]) +
             " is not plain CDR (0,0 big-endian or 0,1 little-endian)";
    return std::nullopt;
  }
  CdrCursor in(data + 4, size - 4, data[1] == 1);
  JointStateMessage m;
  m.stamp_sec = in.Primitive<std::int32_t>("header.stamp.sec");
  m.stamp_nanosec = in.Primitive<std::uint32_t>("header.stamp.nanosec");
  m.frame_id = in.String("header.frame_id");
  m.name = in.Strings("name");
  m.position = in.Doubles("position");
  m.velocity = in.Doubles("velocity");
  m.effort = in.Doubles("effort");
  if (!in.ok()) {
    *error = in.error();
    return std::nullopt;
  }
  return m;
}

}  // namespace massprops::io_internal
