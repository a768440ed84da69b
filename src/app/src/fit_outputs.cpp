#include "plyform/app/fit_outputs.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "plyform/law/user_constants.hpp"

namespace plyform::app {
namespace {

constexpr std::size_t kPerCard = 8;
// Comma-separated fields padded to this width: full double precision (which fixed 10-column
// fields cannot hold) and still columns that line up under their names.
constexpr int kWidth = 16;

std::ofstream open(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
  return out;
}

void close(std::ofstream& out, const std::filesystem::path& file) {
  out.flush();
  if (!out)
    throw std::runtime_error("writing " + file.string() + " failed");
}

/// A CSV cell: quoted when the text holds a comma or a quote.
std::string cell(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string number(double v) {
  return fmt::format("{:.10g}", v);
}

}  // namespace

void write_fit_deck(const std::filesystem::path& file, const std::string& title,
                    std::span<const std::string> comments,
                    std::span<const std::optional<double>> constants,
                    std::span<const law::Curve> curves, int nosid) {
  std::ofstream out = open(file);
  out << "*KEYWORD\n*TITLE\n" << title.substr(0, 80) << "\n";
  for (const std::string& c : comments)
    out << "$ " << c << "\n";
  // Only the curves a constant refers to (-N), with the points the law uses (scale factors
  // and offsets of the original applied).
  for (const law::Curve& c : curves) {
    const bool used = std::any_of(constants.begin(), constants.end(), [&](const auto& v) {
      return v && *v == -static_cast<double>(c.id());
    });
    if (!used)
      continue;
    fmt::print(out, "*DEFINE_CURVE\n$#    LCID\n{:>10}\n$#{:>14},{:>16}\n", c.id(), "A1", "O1");
    for (std::size_t i = 0; i < c.x().size(); ++i)
      fmt::print(out, "{:>16},{:>16}\n", number(c.x()[i]), number(c.y()[i]));
  }
  const auto table = law::user_constant_table();
  fmt::print(out, "*USER_INTERFACE_FRICTION\n$#   NOSID       NOC      NOCI\n{:>10}{:>10}{:>10}\n",
             nosid, constants.size(), 0);
  for (std::size_t first = 0; first < constants.size(); first += kPerCard) {
    const std::size_t last = std::min(constants.size(), first + kPerCard);
    std::string names = "$#";
    std::string values;
    for (std::size_t i = first; i < last; ++i) {
      const std::string name = i < table.size() ? table[i].name : fmt::format("UC{}", i + 1);
      names += fmt::format("{:>{}}", name, i == first ? kWidth - 2 : kWidth);
      values += fmt::format("{:>{}}", constants[i] ? number(*constants[i]) : std::string(), kWidth);
      if (i + 1 < last) {
        names += ",";
        values += ",";
      }
    }
    out << names << "\n" << values << "\n";
  }
  out << "*END\n";
  close(out, file);
}

void write_fit_curves(const std::filesystem::path& file, std::span<const fit::MeasuredCurve> data,
                      const fit::FitResult& result) {
  std::ofstream out = open(file);
  out << "curve,file,point,time,gap,temperature,stress_data,stress_fit,residual,area\n";
  for (std::size_t c = 0; c < data.size(); ++c) {
    const fit::MeasuredCurve& d = data[c];
    const std::vector<double>& fitted = result.curves[c].fitted;
    for (std::size_t i = 0; i < d.path.size(); ++i) {
      const law::PathPoint& p = d.path[i];
      fmt::print(out, "{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", c + 1,
                 cell(d.name), i + 1, p.time, p.gap, p.temperature, d.stress[i], fitted[i],
                 fitted[i] - d.stress[i], d.area);
    }
  }
  close(out, file);
}

}  // namespace plyform::app
