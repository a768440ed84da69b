#pragma once
// Reading back the arrays of a .vtu written by output::VtuSeries (raw appended data: each
// array a UInt64 byte count, then its bytes), for tests that check what a state holds.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace plyform::test {

/// Raw bytes of each appended array, by array name.
inline std::map<std::string, std::string> appended_arrays(const std::string& vtu) {
  const std::size_t marker = vtu.find("<AppendedData encoding=\"raw\">");
  EXPECT_NE(marker, std::string::npos);
  const std::size_t base = vtu.find('_', marker) + 1;
  std::map<std::string, std::string> arrays;
  std::size_t pos = 0;
  while ((pos = vtu.find("<DataArray ", pos)) < marker) {
    const std::size_t end = vtu.find("/>", pos);
    const std::string element = vtu.substr(pos, end - pos);
    const auto attribute = [&](const std::string& name) {
      const std::size_t a = element.find(" " + name + "=\"");
      if (a == std::string::npos) {
        return std::string();
      }
      const std::size_t from = a + name.size() + 3;
      return element.substr(from, element.find('"', from) - from);
    };
    const std::size_t offset = std::stoull(attribute("offset"));
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, vtu.data() + base + offset, sizeof bytes);
    arrays[attribute("Name")] = vtu.substr(base + offset + sizeof bytes, bytes);
    pos = end;
  }
  return arrays;
}

/// An appended Float64 array as doubles.
inline std::vector<double> as_doubles(const std::string& bytes) {
  std::vector<double> values(bytes.size() / sizeof(double));
  if (!values.empty())  // an absent array: no copy (memcpy from null is undefined)
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(double));
  return values;
}

}  // namespace plyform::test
