#pragma once
// The bytes of one message between the ranks of a distributed run (docs/distributed.md): rank 0
// packs what another rank needs (its part of the model, the contact set that every rank holds)
// and the engine sends the bytes. Numbers go as their bytes (the ranks run one build of the tool
// on one kind of machine), arrays with their length first.

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <typename T>
  void put_array(const T* data, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(static_cast<std::uint64_t>(count));
    append(data, count * sizeof(T));
  }
  template <typename T>
  void put(const std::vector<T>& values) {
    put_array(values.data(), values.size());
  }
  void put(const std::vector<bool>& values) {
    std::vector<std::uint8_t> bytes(values.begin(), values.end());
    put(bytes);
  }
  void put(const std::string& text) { put_array(text.data(), text.size()); }
  void put(const std::vector<std::string>& texts) {
    put(static_cast<std::uint64_t>(texts.size()));
    for (const std::string& t : texts) put(t);
  }
  /// A dense matrix (a vector is one column), its shape first.
  void put_matrix(const Eigen::MatrixXd& m) {
    put(static_cast<std::int64_t>(m.rows()));
    put(static_cast<std::int64_t>(m.cols()));
    append(m.data(), static_cast<std::size_t>(m.size()) * sizeof(double));
  }
  void put(const Vector& v) { put_matrix(v); }

  [[nodiscard]] std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
  void append(const void* data, std::size_t size) {
    const auto* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<char>& bytes) : bytes_(bytes) {}

  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    take(&value, sizeof(T));
    return value;
  }
  template <typename T>
  std::vector<T> get_vector() {
    const auto count = static_cast<std::size_t>(get<std::uint64_t>());
    if constexpr (std::is_same_v<T, bool>) {
      std::vector<std::uint8_t> bytes(count);
      take(bytes.data(), count);
      return std::vector<bool>(bytes.begin(), bytes.end());
    } else {
      std::vector<T> values(count);
      take(values.data(), count * sizeof(T));
      return values;
    }
  }
  std::string get_string() {
    const auto count = static_cast<std::size_t>(get<std::uint64_t>());
    std::string text(count, '\0');
    take(text.data(), count);
    return text;
  }
  std::vector<std::string> get_strings() {
    std::vector<std::string> texts(static_cast<std::size_t>(get<std::uint64_t>()));
    for (std::string& t : texts) t = get_string();
    return texts;
  }
  Eigen::MatrixXd get_matrix() {
    const auto rows = static_cast<Index>(get<std::int64_t>());
    const auto cols = static_cast<Index>(get<std::int64_t>());
    Eigen::MatrixXd m(rows, cols);
    take(m.data(), static_cast<std::size_t>(m.size()) * sizeof(double));
    return m;
  }
  Vector get_vector_xd() { return get_matrix().col(0); }
  /// Whether every byte was read: a message read with the layout it was written with.
  [[nodiscard]] bool done() const { return at_ == bytes_.size(); }

 private:
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
  void take(void* data, std::size_t size) {
    if (size > bytes_.size() - at_)
      throw NumericalError("a message between the MPI ranks ended early (a mismatched layout)");
    if (size != 0) std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
  }
};

}  // namespace signorini
