#pragma once
// Test support: small decks written to a fresh temporary folder, and a valid base deck to build on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "crumple/deck/reader.hpp"

namespace crumple::test {

// A temporary folder removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("crumple-test-" + std::to_string(rd()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

// Column helpers so test decks read like real ones: I(v) is a 10-column integer, R(v) a 20-column real.
inline std::string I(long long v) {
  std::string s = std::to_string(v);
  return std::string(s.size() < 10 ? 10 - s.size() : 0, ' ') + s;
}
inline std::string R(const std::string& v) { return std::string(v.size() < 20 ? 20 - v.size() : 0, ' ') + v; }
inline std::string R(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return R(std::string(buffer));
}
inline std::string blank(int columns) { return std::string(static_cast<std::size_t>(columns), ' '); }

// /BEGIN with kg, m, s in and out.
inline std::string begin_card(const std::string& name = "TEST", int input_version = 2019) {
  return "/BEGIN\n" + name + "\n" + I(input_version) + "         0\n" + R("kg") + R("m") + R("s") + "\n" + R("kg") +
         R("m") + R("s") + "\n";
}

// One steel plate of 2 x 1 four-node shells (6 nodes), part 1, property 1 (t = 0.001), material 1 (elastic).
inline std::string plate_cards() {
  std::string s;
  s += "/NODE\n";
  const double xs[3] = {0.0, 0.01, 0.02};
  int id = 1;
  for (double y : {0.0, 0.01})
    for (double x : xs) s += I(id++) + R(x) + R(y) + R(0.0) + "\n";
  s += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(5) + I(4) + "\n" + I(2) + I(2) + I(3) + I(6) + I(5) + "\n";
  s += "/PART/1\nplate\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(3) + I(0) + R(0.001) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  return s;
}

inline std::string engine_cards(double end_time = 1e-3) {
  return "/RUN/TEST/1\n" + std::to_string(end_time) + "\n/TFILE\n1e-4\n/ANIM/DT\n0 1e-3\n";
}

// A valid two-file deck with `extra` starter cards inserted before /END; returns the starter path.
inline std::filesystem::path write_deck(const TempDir& dir, const std::string& extra = "",
                                        const std::string& engine = engine_cards()) {
  dir.write("TEST_0001.rad", engine);
  return dir.write("TEST_0000.rad", begin_card() + plate_cards() + extra + "/END\n");
}

// Reads a deck expected to fail and returns the text of the first error (empty when it read fine).
inline std::string first_error(const std::filesystem::path& starter, const ReadOptions& options = {}) {
  try {
    read_deck(starter, options);
  } catch (const DeckErrors& e) {
    return e.errors().front().what();
  } catch (const DeckError& e) {
    return e.what();
  }
  return {};
}

}  // namespace crumple::test
