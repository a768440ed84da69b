#include "plyform/fit/free_constants.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <sstream>

#include "plyform/fit/measured_curve.hpp"
#include "plyform/law/user_constants.hpp"

namespace plyform::fit {
namespace {

// The constants the normal traction of a driven point depends on. Switches (MODEL, FRIC,
// COUPLING) are not continuous, BOND_TOL only decides the initial state, and the friction and
// damping constants act on the tangential traction or need a mass the driver does not have.
constexpr std::array<std::string_view, 10> kFittable{
    "CN", "SMAX_LO", "SMAX_HI", "T_LO", "T_HI", "ETA", "ZETA_LO", "ZETA_HI", "BETA0", "BETA_MIN"};

const law::ConstantSpec* spec_named(std::string_view name) {
  for (const law::ConstantSpec& s : law::user_constant_table()) {
    if (name == s.name)
      return &s;
  }
  return nullptr;
}

std::string fittable_list() {
  return "CN, SMAX (SMAX_LO and SMAX_HI as one), SMAX_LO, SMAX_HI, T_LO, T_HI, ETA, ZETA "
         "(ZETA_LO and ZETA_HI as one), ZETA_LO, ZETA_HI, BETA0, BETA_MIN";
}

FreeConstant make(std::string name) {
  FreeConstant c;
  std::vector<std::string_view> names;
  if (name == "SMAX")
    names = {"SMAX_LO", "SMAX_HI"};
  else if (name == "ZETA")
    names = {"ZETA_LO", "ZETA_HI"};
  else
    names = {name};
  for (std::string_view n : names) {
    const law::ConstantSpec* s = spec_named(n);
    if (s == nullptr) {
      throw FitError("--free: unknown constant '" + name + "'; the law's constants that a fit " +
                     "can vary are " + fittable_list());
    }
    if (std::find(kFittable.begin(), kFittable.end(), n) == kFittable.end()) {
      throw FitError("--free: constant " + name + " (UC" + std::to_string(s->index) + ", " +
                     s->meaning + ") cannot be fitted to normal traction curves; the constants " +
                     "that can are " + fittable_list());
    }
    c.slots.push_back(s->index);
    if (s->min == 0.0 && std::isinf(s->max))
      c.transform = Transform::log;
    else if (s->min == 0.0 && s->max == 1.0)
      c.transform = Transform::logit;
    else
      c.transform = Transform::linear;
  }
  c.name = std::move(name);
  return c;
}

}  // namespace

std::vector<FreeConstant> parse_free_constants(std::string_view list) {
  std::vector<FreeConstant> out;
  std::string token;
  const auto flush = [&] {
    if (token.empty())
      return;
    for (const FreeConstant& c : out) {
      for (int slot : make(token).slots) {
        if (std::find(c.slots.begin(), c.slots.end(), slot) != c.slots.end())
          throw FitError("--free: constant " + token + " is named twice (as " + c.name + ")");
      }
    }
    out.push_back(make(token));
    token.clear();
  };
  for (char ch : list) {
    if (ch == ',' || std::isspace(static_cast<unsigned char>(ch)) != 0)
      flush();
    else
      token.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(ch))));
  }
  flush();
  if (out.empty())
    throw FitError("--free: no constant named; give e.g. --free CN,SMAX,ETA");
  return out;
}

double value_of(const FreeConstant& c, std::span<const std::optional<double>> uc) {
  const auto i = static_cast<std::size_t>(c.slots.front() - 1);
  if (i < uc.size() && uc[i])
    return *uc[i];
  return law::user_constant_table()[i].default_value;
}

void set_value(const FreeConstant& c, double value, std::vector<std::optional<double>>& uc) {
  for (int slot : c.slots) {
    const auto i = static_cast<std::size_t>(slot - 1);
    if (uc.size() <= i)
      uc.resize(i + 1);
    uc[i] = value;
  }
}

double to_variable(const FreeConstant& c, double value) {
  switch (c.transform) {
    case Transform::log:
      return std::log(value);
    case Transform::logit:
      return std::log(value / (1.0 - value));
    case Transform::linear:
      break;
  }
  return value / c.scale;
}

double from_variable(const FreeConstant& c, double x) {
  switch (c.transform) {
    case Transform::log:
      return std::exp(x);
    case Transform::logit:
      return 1.0 / (1.0 + std::exp(-x));
    case Transform::linear:
      break;
  }
  return x * c.scale;
}

double value_derivative(const FreeConstant& c, double x) {
  switch (c.transform) {
    case Transform::log:
      return std::exp(x);
    case Transform::logit: {
      const double v = 1.0 / (1.0 + std::exp(-x));
      return v * (1.0 - v);
    }
    case Transform::linear:
      break;
  }
  return c.scale;
}

void check_start(const FreeConstant& c, std::span<const std::optional<double>> uc) {
  const double v = value_of(c, uc);
  for (int slot : c.slots) {
    const auto i = static_cast<std::size_t>(slot - 1);
    const double vi = i < uc.size() && uc[i] ? *uc[i] : v;
    const law::ConstantSpec& s = law::user_constant_table()[i];
    if (s.temperature_dependent && vi < 0.0) {
      throw FitError("--free: " + std::string(s.name) + " is given by load curve " +
                     std::to_string(static_cast<long>(-vi)) +
                     " in the starting deck; a fit varies numbers, not curves");
    }
    if (vi != v) {
      std::ostringstream os;
      os << "--free: " << c.name << " ties " << law::user_constant_table()[c.slots[0] - 1].name
         << " = " << v << " and " << s.name << " = " << vi
         << ", which differ in the starting constants; free them separately";
      throw FitError(os.str());
    }
  }
  const bool ok = c.transform == Transform::log     ? v > 0.0
                  : c.transform == Transform::logit ? v > 0.0 && v < 1.0
                                                    : std::isfinite(v);
  if (!ok) {
    std::ostringstream os;
    os << "--free: " << c.name << " starts at " << v << "; a fitted "
       << (c.transform == Transform::log ? "positive constant must start above 0"
                                         : "constant of [0, 1] must start strictly between them")
       << " (give a starting value in --deck)";
    throw FitError(os.str());
  }
}

}  // namespace plyform::fit
