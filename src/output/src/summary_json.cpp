#include "plyform/output/summary_json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <string_view>

#include "atomic_file.hpp"

namespace plyform::output {
namespace {

/// Length of the valid UTF-8 sequence starting at text[i], or 0 when it is not valid.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  std::uint32_t code = 0;
  if (lead < 0x80) {
    return 1;
  } else if ((lead & 0xE0) == 0xC0) {
    length = 2;
    code = lead & 0x1Fu;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3;
    code = lead & 0x0Fu;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4;
    code = lead & 0x07u;
  } else {
    return 0;
  }
  if (i + length > text.size()) {
    return 0;
  }
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) {
      return 0;
    }
    code = (code << 6) | (byte(i + k) & 0x3Fu);
  }
  const std::uint32_t minimum = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
  if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
    return 0;  // overlong, out of range or a surrogate
  }
  return length;
}

void append_number(std::string& out, double value) {
  if (std::isfinite(value)) {
    fmt::format_to(std::back_inserter(out), "{}", value);
  } else {
    out += "null";
  }
}

}  // namespace

std::string json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      default:
        if (u < 0x20 || u == 0x7F) {
          fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<unsigned>(u));
        } else if (u >= 0x80) {
          const std::size_t length = utf8_sequence_length(text, i);
          if (length == 0) {
            out += "\\ufffd";
            ++i;
          } else {
            out.append(text.substr(i, length));
            i += length;
          }
          continue;
        } else {
          out += c;
        }
    }
    ++i;
  }
  out += '"';
  return out;
}

std::string summary_json_text(const RunSummary& s) {
  std::string out = "{\n";
  const auto key = [&out](std::string_view name) {
    out += "  \"";
    out += name;
    out += "\": ";
  };
  const auto text = [&](std::string_view name, std::string_view value) {
    key(name);
    out += json_string(value);
    out += ",\n";
  };
  const auto integer = [&](std::string_view name, long value) {
    key(name);
    fmt::format_to(std::back_inserter(out), "{},\n", value);
  };
  const auto real = [&](std::string_view name, double value) {
    key(name);
    append_number(out, value);
    out += ",\n";
  };
  text("status", s.status);
  text("deck", s.deck);
  text("version", s.version);
  integer("cycles", s.cycles);
  real("final_time", s.final_time);
  real("end_time", s.end_time);
  real("wall_seconds", s.wall_seconds);
  real("element_cycles_per_second", s.element_cycles_per_second);
  real("energy_ratio", s.energy_ratio);
  real("dt_initial", s.dt_initial);
  real("dt_final", s.dt_final);
  real("added_mass", s.added_mass);
  real("added_mass_ratio", s.added_mass_ratio);
  integer("nodes", s.nodes);
  integer("elements", s.elements);
  integer("deformable_elements", s.deformable_elements);
  integer("threads", s.threads);
  integer("ranks", s.ranks);
  key("rebalancing");
  fmt::format_to(std::back_inserter(out), "{{\"splits\": {}, \"shares\": [", s.rebalancing.splits);
  for (std::size_t i = 0; i < s.rebalancing.shares.size(); ++i) {
    out += i > 0 ? ", " : "";
    append_number(out, s.rebalancing.shares[i]);
  }
  out += "], \"first_imbalance\": ";
  append_number(out, s.rebalancing.first_imbalance);
  out += ", \"last_imbalance\": ";
  append_number(out, s.rebalancing.last_imbalance);
  out += "},\n";
  key("moved_nodes");
  out += "[";
  for (std::size_t i = 0; i < s.moved_nodes.size(); ++i)
    fmt::format_to(std::back_inserter(out), "{}{}", i > 0 ? ", " : "", s.moved_nodes[i]);
  out += "],\n";
  real("restarted_at", s.restarted_at);
  text("checkpoint", s.checkpoint);
  integer("thermal_steps", s.thermal_steps);
  integer("thermal_iterations", s.thermal_iterations);
  real("heat_stored", s.heat_stored);
  real("heat_entered", s.heat_entered);
  key("warnings");
  if (s.warnings.empty()) {
    out += "[],\n";
  } else {
    out += "[\n";
    for (std::size_t i = 0; i < s.warnings.size(); ++i) {
      out += "    ";
      out += json_string(s.warnings[i]);
      out += i + 1 < s.warnings.size() ? ",\n" : "\n";
    }
    out += "  ],\n";
  }
  key("distrust");
  if (s.distrust.empty()) {
    out += "[],\n";
  } else {
    out += "[\n";
    for (std::size_t i = 0; i < s.distrust.size(); ++i) {
      out += "    {\"reason\": ";
      out += json_string(s.distrust[i].reason);
      out += ", \"time\": ";
      append_number(out, s.distrust[i].time);
      out += i + 1 < s.distrust.size() ? "},\n" : "}\n";
    }
    out += "  ],\n";
  }
  key("timing");
  out += "{\"loop_seconds\": ";
  append_number(out, s.loop_seconds);
  out += ", \"passes\": [";
  for (std::size_t i = 0; i < s.timing.size(); ++i) {
    const RunSummary::PassTime& x = s.timing[i];
    out += "\n    {\"group\": ";
    out += json_string(x.group);
    out += ", \"pass\": ";
    out += json_string(x.pass);
    out += ", \"seconds\": ";
    append_number(out, x.seconds);
    out += ", \"share\": ";
    append_number(out, s.loop_seconds > 0.0 ? x.seconds / s.loop_seconds : 0.0);
    out += i + 1 < s.timing.size() ? "}," : "}";
  }
  out += s.timing.empty() ? "]},\n" : "\n  ]},\n";
  key("rank_timing");
  out += "[";
  for (std::size_t i = 0; i < s.rank_timing.size(); ++i) {
    const RunSummary::RankTiming& x = s.rank_timing[i];
    out += "\n    {\"rank\": ";
    out += std::to_string(x.rank);
    out += ", \"loop_seconds\": ";
    append_number(out, x.loop_seconds);
    out += ", \"groups\": {";
    for (std::size_t g = 0; g < x.groups.size(); ++g) {
      out += json_string(x.groups[g].first);
      out += ": ";
      append_number(out, x.groups[g].second);
      if (g + 1 < x.groups.size())
        out += ", ";
    }
    out += i + 1 < s.rank_timing.size() ? "}}," : "}}";
  }
  out += s.rank_timing.empty() ? "]\n" : "\n  ]\n";
  out += "}\n";
  return out;
}

void write_summary_json(const std::filesystem::path& file, const RunSummary& summary) {
  const std::string text = summary_json_text(summary);
  detail::AtomicFile out(file);
  out.write(text);
  out.commit();
}

}  // namespace plyform::output
