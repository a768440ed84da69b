#pragma once
// Helpers shared by the validation passes (validate_mesh, validate_contact): ids of one kind
// with where each was defined, and located "is not defined" errors for references.

#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/model/source_location.hpp"

namespace plyform::setup::detail {

/// Concatenates values as text (fmt is not a dependency of this library).
template <typename... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

inline std::string at(const model::SourceLocation& w) {
  return cat(w.file, ":", w.line);
}

/// Ids of one kind with where each was first defined.
class IdTable {
 public:
  IdTable(std::string_view noun, std::string_view keyword) : noun_(noun), keyword_(keyword) {}

  /// Adds an id; a duplicate is an error on the later definition.
  void add(int id, const model::SourceLocation& where, std::string_view field,
           std::vector<keyword::Diagnostic>& errors, std::string_view keyword = {}) {
    const auto [it, inserted] = ids_.emplace(id, where);
    if (!inserted) {
      errors.push_back({where, std::string(keyword.empty() ? keyword_ : keyword),
                        std::string(field),
                        cat(noun_, " ", id, " is already defined at ", at(it->second))});
    }
  }
  bool contains(int id) const { return ids_.contains(id); }
  std::string_view noun() const { return noun_; }
  std::string_view keyword() const { return keyword_; }

 private:
  std::string noun_;
  std::string keyword_;
  std::unordered_map<int, model::SourceLocation> ids_;
};

/// Reports a reference to an id the table does not hold.
inline void check_ref(const IdTable& table, int id, const model::SourceLocation& where,
                      std::string_view keyword, std::string_view field,
                      std::vector<keyword::Diagnostic>& errors) {
  if (!table.contains(id)) {
    errors.push_back(
        {where, std::string(keyword), std::string(field),
         cat(table.noun(), " ", id, " is not defined (no ", table.keyword(), " with this id)")});
  }
}

}  // namespace plyform::setup::detail
