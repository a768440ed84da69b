#include "build_tables.hpp"

namespace plyform::setup {

std::unordered_map<int, core::CurveTable> build_tables(const model::ModelDesc& deck) {
  std::unordered_map<int, core::CurveTable> out;
  for (const model::DefineTableDesc& t : deck.tables) {
    core::CurveTable table;
    table.value = model::effective_values(t);
    for (std::size_t i = t.first_curve;
         i < deck.curves.size() && table.curve.size() < t.values.size(); ++i) {
      core::LoadCurve c;
      for (const model::CurvePoint& p : model::effective_points(deck.curves[i])) {
        c.x.push_back(p.x);
        c.y.push_back(p.y);
      }
      table.curve.push_back(std::move(c));
    }
    table.value.resize(table.curve.size());
    out.emplace(t.id, std::move(table));
  }
  return out;
}

}  // namespace plyform::setup
