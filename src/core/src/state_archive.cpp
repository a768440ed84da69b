#include "plyform/core/state_archive.hpp"

namespace plyform::core {

std::string StateArchive::full(std::string_view name) const {
  std::string s = prefix_;
  s.append(name);
  return s;
}

void StateArchive::put(std::string_view name, std::uint32_t element_size, const void* data,
                       std::size_t bytes) {
  std::string record(kHeader + bytes, '\0');
  std::memcpy(record.data(), &element_size, kHeader);
  if (bytes > 0)
    std::memcpy(record.data() + kHeader, data, bytes);
  const auto [it, added] = records_.emplace(full(name), std::move(record));
  if (!added)
    throw StateError("checkpoint record '" + it->first + "' saved twice");
}

const std::string& StateArchive::get(std::string_view name, std::uint32_t element_size) const {
  const std::string key = full(name);
  const auto it = source_->find(key);
  if (it == source_->end())
    throw StateError("the checkpoint has no record '" + key + "'");
  std::uint32_t size = 0;
  if (it->second.size() >= kHeader)
    std::memcpy(&size, it->second.data(), kHeader);
  if (it->second.size() < kHeader || size != element_size ||
      (it->second.size() - kHeader) % element_size != 0) {
    throw StateError("checkpoint record '" + key + "' has values of " + std::to_string(size) +
                     " bytes where the model has " + std::to_string(element_size));
  }
  return it->second;
}

void StateArchive::strings(std::string_view name, std::vector<std::string>& values) {
  // Lengths in one record, the texts joined in another.
  std::vector<std::uint64_t> lengths;
  std::vector<char> text;
  if (saving_) {
    for (const std::string& s : values) {
      lengths.push_back(s.size());
      text.insert(text.end(), s.begin(), s.end());
    }
  }
  const std::string n(name);
  array(n + ".lengths", lengths);
  array(n + ".text", text);
  if (!saving_) {
    values.clear();
    std::size_t at = 0;
    for (std::uint64_t l : lengths) {
      if (at + l > text.size())
        throw StateError("checkpoint record '" + full(n) + "' is inconsistent");
      values.emplace_back(text.data() + at, static_cast<std::size_t>(l));
      at += static_cast<std::size_t>(l);
    }
  }
}

}  // namespace plyform::core
