// `plyform fit`: the law's constants from measured traction-opening curves, by least squares
// through the same point driver as `plyform law`; writes FIT.k, FIT_curves.csv and a plot.

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <ostream>

#include "plyform/app/commands.hpp"
#include "plyform/app/fit_outputs.hpp"
#include "plyform/app/fit_report.hpp"
#include "plyform/app/path_csv.hpp"
#include "plyform/app/probe_csv.hpp"
#include "plyform/app/python_script.hpp"
#include "plyform/fit/fit.hpp"
#include "plyform/fit/free_constants.hpp"
#include "plyform/fit/starting_values.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/law/user_constants.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/validate.hpp"

namespace plyform::app {
namespace {

constexpr int kInputError = 1;
constexpr int kOutputError = 2;
constexpr int kNotMeaningful = 3;

/// The starting law: constants, the load curves they refer to, the NOSID of the card.
struct Start {
  std::vector<std::optional<double>> constants;
  std::vector<law::Curve> curves;
  int nosid = 1;
  std::string source;
};

/// The starting law of a deck's *USER_INTERFACE_FRICTION, or nothing after printing why.
std::optional<Start> start_from_deck(const std::filesystem::path& deck,
                                     std::optional<int> interface_id, std::ostream& err) {
  const auto print = [&](const std::vector<keyword::Diagnostic>& errors) {
    for (const auto& d : errors)
      fmt::print(err, "error: {}\n", d.to_string());
  };
  const keyword::ReadResult read = keyword::read_deck(deck);
  if (!read.ok()) {
    print(read.errors);
    return std::nullopt;
  }
  if (const auto errors = setup::validate(read.model); !errors.empty()) {
    print(errors);
    return std::nullopt;
  }
  const auto& uifs = read.model.user_interface_frictions;
  const model::UserInterfaceFrictionDesc* uif = nullptr;
  for (const auto& u : uifs) {
    if (interface_id ? u.contact_id == *interface_id : uifs.size() == 1)
      uif = &u;
  }
  if (uif == nullptr) {
    fmt::print(
        err, "error: {}: {}\n", deck.string(),
        interface_id   ? fmt::format("no *USER_INTERFACE_FRICTION with NOSID {}", *interface_id)
        : uifs.empty() ? std::string("the deck has no *USER_INTERFACE_FRICTION to start from")
                       : fmt::format("the deck has {} *USER_INTERFACE_FRICTION cards; choose one "
                                     "with --interface NOSID",
                                     uifs.size()));
    return std::nullopt;
  }
  const setup::CohesiveLawBuild built = setup::build_cohesive_law(read.model, *uif);
  if (!built.parameters) {
    print(built.errors);
    return std::nullopt;
  }
  Start s;
  s.constants = law::to_user_constants(*built.parameters);
  s.curves = built.parameters->curves;
  s.nosid = uif->contact_id;
  s.source = fmt::format("{} (*USER_INTERFACE_FRICTION NOSID {})", deck.string(), s.nosid);
  return s;
}

/// One value for every curve, one per curve, or none; nullopt after printing why not.
std::optional<std::vector<std::optional<double>>> per_curve(const std::vector<double>& values,
                                                            std::size_t curves, const char* option,
                                                            std::ostream& err) {
  std::vector<std::optional<double>> out(curves);
  if (values.size() == 1)
    std::fill(out.begin(), out.end(), values.front());
  else if (values.size() == curves)
    std::copy(values.begin(), values.end(), out.begin());
  else if (!values.empty()) {
    fmt::print(err, "error: {} takes one value for all curves or one per curve ({}), got {}\n",
               option, curves, values.size());
    return std::nullopt;
  }
  return out;
}

std::filesystem::path sibling(const std::filesystem::path& deck, const std::string& suffix) {
  return deck.parent_path() / (deck.stem().string() + suffix);
}

}  // namespace

int run_fit(const FitOptions& options, std::ostream& out, std::ostream& err) {
  if (options.curves.empty()) {
    fmt::print(err, "error: no curve file to fit\n");
    return kInputError;
  }
  const auto rates = per_curve(options.rates, options.curves.size(), "--rate", err);
  const auto areas = per_curve(options.areas, options.curves.size(), "--area", err);
  if (!rates || !areas)
    return kInputError;

  std::vector<fit::FreeConstant> free;
  std::optional<Start> start;
  std::vector<fit::MeasuredCurve> data;
  std::vector<std::string> notes;
  try {
    free = fit::parse_free_constants(options.free);
    if (options.deck) {
      start = start_from_deck(*options.deck, options.interface_id, err);
      if (!start)
        return kInputError;
    }
    // Curves without a temperature column are at --temperature, else at T_LO of the start.
    std::optional<double> temperature = options.temperature;
    if (!temperature && start)
      temperature = start->constants[4].value_or(0.0);
    for (std::size_t i = 0; i < options.curves.size(); ++i) {
      ProbeCurve c = read_probe_csv(options.curves[i], {(*rates)[i], (*areas)[i], temperature});
      for (const std::string& n : c.notes)
        notes.push_back(c.curve.name + ": " + n);
      data.push_back(std::move(c.curve));
    }
    if (!start) {
      start = Start{};
      start->constants = fit::default_start(data, notes);
      start->source = "the curves (no --deck)";
    }
    fit::complete_start(free, data, start->constants, notes);
  } catch (const std::exception& e) {  // PathError, FitError
    fmt::print(err, "error: {}\n", e.what());
    return kInputError;
  }

  std::string free_names;
  for (const auto& f : free)
    free_names += (free_names.empty() ? "" : ", ") + f.name;
  std::size_t points = 0;
  for (const auto& d : data)
    points += d.path.size();
  fmt::print(out, "plyform fit: {} curve(s), {} points; free: {}; start: {}\n", data.size(), points,
             free_names, start->source);
  for (const std::string& n : notes)
    fmt::print(out, "note: {}\n", n);

  fit::FitSettings settings;
  settings.model.penalty = options.penalty.value_or(0.0);
  settings.model.substeps = options.substeps;
  fit::FitResult result;
  try {
    result = fit::fit_constants(start->constants, start->curves, data, free, settings);
  } catch (const std::exception& e) {
    fmt::print(err, "error: the law cannot be fitted to these curves:\n");
    std::string text = e.what();
    for (std::size_t a = 0, b; a < text.size(); a = b + 1) {
      b = text.find('\n', a);
      if (b == std::string::npos)
        b = text.size();
      fmt::print(err, "  {}\n", text.substr(a, b - a));
    }
    return kInputError;
  }
  const std::vector<std::string> report = fit_report(result, data);
  for (const std::string& line : report)
    fmt::print(out, "{}\n", line);
  for (const std::string& w : result.warnings)
    fmt::print(err, "warning: {}\n", w);

  const std::filesystem::path deck =
      options.output ? *options.output
                     : std::filesystem::path(options.curves.front().stem().string() + "_fit.k");
  const std::filesystem::path curves_csv = sibling(deck, "_curves.csv");
  const std::filesystem::path png = sibling(deck, "_curves.png");
  std::vector<std::string> written;
  try {
    if (!deck.parent_path().empty())
      std::filesystem::create_directories(deck.parent_path());
    write_fit_curves(curves_csv, data, result);
    written.push_back(curves_csv.string());
    if (result.meaningful()) {
      std::vector<std::string> comments{
          "Fitted by plyform fit (least squares through the law's "
          "point driver) to:"};
      for (std::size_t i = 0; i < data.size(); ++i)
        comments.push_back(fmt::format("  curve {}: {}", i + 1, options.curves[i].string()));
      comments.push_back("Starting constants: " + start->source);
      comments.insert(comments.end(), report.begin(), report.end());
      write_fit_deck(deck, "plyform fit: " + free_names + " from " + data.front().name, comments,
                     result.constants, start->curves, start->nosid);
      written.insert(written.begin(), deck.string());
    }
  } catch (const std::exception& e) {
    fmt::print(err, "error: {}\n", e.what());
    return kOutputError;
  }
  if (options.plot) {
    out.flush();
    const ScriptRun plot = run_python_script("plot_fit.py", {curves_csv.string(), png.string()});
    if (plot.problem.empty())
      written.push_back(png.string());
    else
      fmt::print(err, "note: no plot: {}\n", plot.problem);
  }
  std::string list;
  for (const std::string& w : written)
    list += (list.empty() ? "" : ", ") + w;
  fmt::print(out, "wrote {}\n", list);

  if (!result.meaningful()) {
    fmt::print(err, "error: the fit is not meaningful, {} not written:\n", deck.string());
    for (const std::string& p : result.problems)
      fmt::print(err, "  {}\n", p);
    return kNotMeaningful;
  }
  return 0;
}

}  // namespace plyform::app
