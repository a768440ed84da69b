#pragma once
// A run's state as named flat records, for checkpoints. Each owner of state (the simulation,
// its element blocks, the rigid bodies, each contact pass, the output writer) lists its fields
// once, in one visit_state(StateArchive&) that both saves and restores them, so that the two
// directions cannot drift apart. A record is a name and the bytes of a trivially copyable value
// or array; names nest with scope() ("contact/2/gap").

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace plyform::core {

/// A checkpoint whose records do not fit the model (a missing record, another element size or
/// count): the message names the record.
class StateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  using Records = std::map<std::string, std::string, std::less<>>;

  /// An archive that collects records (visit_state saves).
  static StateArchive for_saving() { return StateArchive(true, {}); }
  /// An archive that hands out `records` (visit_state restores); they must outlive it.
  static StateArchive for_loading(const Records& records) {
    StateArchive a(false, {});
    a.source_ = &records;
    return a;
  }

  [[nodiscard]] bool saving() const { return saving_; }
  [[nodiscard]] const Records& records() const { return records_; }
  [[nodiscard]] Records take_records() { return std::move(records_); }

  /// Names get `name/` in front while the returned guard lives.
  class Scope {
   public:
    Scope(StateArchive& a, std::string_view name) : a_(a), size_(a.prefix_.size()) {
      a_.prefix_.append(name);
      a_.prefix_ += '/';
    }
    ~Scope() { a_.prefix_.resize(size_); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    StateArchive& a_;
    std::size_t size_;
  };
  [[nodiscard]] Scope scope(std::string_view name) { return Scope(*this, name); }
  [[nodiscard]] Scope scope(std::size_t index) { return Scope(*this, std::to_string(index)); }

  /// One value.
  template <class T>
  void value(std::string_view name, T& v) {
    fixed(name, std::span<T>(&v, 1));
  }
  /// An array whose length the model fixes: restoring checks the count.
  template <class T>
  void fixed(std::string_view name, std::span<T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (saving_) {
      put(name, sizeof(T), values.data(), values.size_bytes());
      return;
    }
    const std::string& r = get(name, sizeof(T));
    const std::size_t count = (r.size() - kHeader) / sizeof(T);
    if (count != values.size()) {
      throw StateError("checkpoint record '" + full(name) + "' holds " + std::to_string(count) +
                       " values where the model has " + std::to_string(values.size()));
    }
    if (!values.empty())
      std::memcpy(values.data(), r.data() + kHeader, values.size_bytes());
  }
  /// An array whose length is state too (resized on restore).
  template <class T>
  void array(std::string_view name, std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (saving_) {
      put(name, sizeof(T), values.data(), values.size() * sizeof(T));
      return;
    }
    const std::string& r = get(name, sizeof(T));
    values.resize((r.size() - kHeader) / sizeof(T));
    if (!values.empty())
      std::memcpy(values.data(), r.data() + kHeader, values.size() * sizeof(T));
  }
  /// Texts (warnings, file names).
  void strings(std::string_view name, std::vector<std::string>& values);

 private:
  static constexpr std::size_t kHeader = 4;  // the element size, uint32
  StateArchive(bool saving, Records records) : saving_(saving), records_(std::move(records)) {}
  [[nodiscard]] std::string full(std::string_view name) const;
  void put(std::string_view name, std::uint32_t element_size, const void* data, std::size_t bytes);
  [[nodiscard]] const std::string& get(std::string_view name, std::uint32_t element_size) const;

  bool saving_;
  Records records_;                  // saving: what visit_state gave
  const Records* source_ = nullptr;  // loading
  std::string prefix_;
};

}  // namespace plyform::core
