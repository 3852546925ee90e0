#include "scene/obj_check.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/file_access.hpp"

namespace glintlab {

namespace {

/// The digits of a number's exponent ("1e-308": 3; 0 without one).
std::size_t exponent_digits(const std::string& token) {
  const auto e = token.find_first_of("eE");
  const auto first = e == std::string::npos ? std::string::npos : token.find_first_not_of("+-", e + 1);
  return first == std::string::npos ? 0 : token.size() - first;
}

// The three lists a face indexes, in the order of an `f` reference v/vt/vn.
enum class ObjList { Position, Uv, Normal };

const char* statement_of(ObjList list) {
  switch (list) {
    case ObjList::Position: return "v";
    case ObjList::Uv: return "vt";
    case ObjList::Normal: return "vn";
  }
  return "";
}

const char* name_of(ObjList list) {
  switch (list) {
    case ObjList::Position: return "position";
    case ObjList::Uv: return "uv";
    case ObjList::Normal: return "normal";
  }
  return "";
}

// A positive index may refer to a line after the face; it is checked once the whole file is read.
struct ForwardReference {
  std::size_t line;
  ObjList list;
  long value;
};

class ObjChecker {
 public:
  explicit ObjChecker(const std::filesystem::path& path) : file_(path.string()), directory_(path.parent_path().string()) {}

  void statement(std::size_t line, std::istringstream& tokens) {
    std::string command;
    tokens >> command;
    if (command == "v") {
      check_numbers(line, command, tokens);
      ++count_[index(ObjList::Position)];
    } else if (command == "vn") {
      check_numbers(line, command, tokens);
      ++count_[index(ObjList::Normal)];
    } else if (command == "vt") {
      check_numbers(line, command, tokens);
      ++count_[index(ObjList::Uv)];
    } else if (command == "vw") {
      // tinyobjloader's skin weights (glintlab ignores them): it casts each joint id to int, and
      // reads to the line's end, '#' included (finding 20).
      check_numbers(line, command, tokens, 1e9, false);
    } else if (command == "f") {
      for (std::string ref; tokens >> ref && ref[0] != '#';) check_face_reference(line, ref);
    } else if (command == "mtllib") {
      for (std::string name; tokens >> name && name[0] != '#';) check_material_library(line, name);
    }
  }

  void finish() const {
    for (const auto& f : forward_)
      if (static_cast<std::size_t>(f.value) > count_[index(f.list)]) fail_index(f.line, f.list, f.value, count_[index(f.list)], true);
  }

 private:
  static std::size_t index(ObjList list) { return static_cast<std::size_t>(list); }

  // Values are stored as float: anything past FLT_MAX (1e39) is as unusable as nan or inf.
  void check_numbers(std::size_t line, const std::string& command, std::istringstream& tokens,
                     double max_magnitude = std::numeric_limits<float>::max(), bool comments = true) const {
    for (std::string token; tokens >> token && !(comments && token[0] == '#');) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      // tinyobjloader reads an exponent into an int and overflows past 9 digits (fuzz/fuzz_obj.cpp,
      // docs/fuzzing.md finding 15); no float needs more than 3.
      const bool is_number = end == token.c_str() + token.size() && !token.empty() && exponent_digits(token) <= 3;
      if (!is_number || !std::isfinite(value) || std::abs(value) > max_magnitude) {
        std::ostringstream s;
        s << file_ << ':' << line << ": `" << command << "` value " << token << " is not a finite number; allowed: "
          << "numbers of magnitude at most " << max_magnitude << ", exponents of at most 3 digits";
        throw InputError(s.str());
      }
    }
  }

  // tinyobjloader reads a material library wherever it opens, to its end: /dev/zero or a FIFO never
  // ends. It looks in the OBJ's directory (split at ':', as a search path) joined with the name.
  void check_material_library(std::size_t line, const std::string& name) const {
    std::istringstream directories(directory_);
    for (std::string directory; std::getline(directories, directory, ':');) {
      const std::filesystem::path candidate =
          directory.empty() || directory.back() == '/' ? directory + name : directory + '/' + name;
      std::error_code ec;
      if (std::filesystem::exists(candidate, ec) && !std::filesystem::is_regular_file(candidate, ec)) {
        std::ostringstream s;
        s << file_ << ':' << line << ": `mtllib` " << name << " is " << candidate.string()
          << ", not a regular file; allowed: a regular file or none (glintlab ignores OBJ materials)";
        throw InputError(s.str());
      }
    }
  }

  void check_face_reference(std::size_t line, const std::string& ref) {
    // v, v/vt, v//vn or v/vt/vn
    std::size_t begin = 0;
    for (ObjList list : {ObjList::Position, ObjList::Uv, ObjList::Normal}) {
      const std::size_t slash = ref.find('/', begin);
      const std::string part = ref.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin);
      if (!part.empty() || list == ObjList::Position) check_index(line, list, part);
      if (slash == std::string::npos) break;
      begin = slash + 1;
    }
  }

  void check_index(std::size_t line, ObjList list, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    const std::size_t so_far = count_[index(list)];
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || value == 0) {
      std::ostringstream s;
      s << file_ << ':' << line << ": `f` " << name_of(list) << " index '" << text
        << "' is not a nonzero integer; allowed: 1 to N for the Nth `" << statement_of(list)
        << "` line, or -1 to -N counting back from the face";
      throw InputError(s.str());
    }
    if (value < 0 && static_cast<std::size_t>(-value) > so_far) fail_index(line, list, value, so_far, false);
    if (value > 0 && static_cast<std::size_t>(value) > so_far) forward_.push_back({line, list, value});
  }

  [[noreturn]] void fail_index(std::size_t line, ObjList list, long value, std::size_t count, bool whole_file) const {
    std::ostringstream s;
    s << file_ << ':' << line << ": `f` " << name_of(list) << " index " << value << " is out of range; allowed: ";
    const char* statement = statement_of(list);
    if (count == 0) {
      s << "none, " << (whole_file ? "the file has" : "the face follows") << " no `" << statement << "` line";
    } else if (whole_file) {
      s << "1 to " << count << " (the file has " << count << " `" << statement << "` line" << (count == 1 ? ")" : "s)");
    } else {
      s << "-1 to -" << count << " (the face follows " << count << " `" << statement << "` line" << (count == 1 ? ")" : "s)");
    }
    throw InputError(s.str());
  }

  std::string file_;
  std::string directory_;
  std::size_t count_[3] = {0, 0, 0};
  std::vector<ForwardReference> forward_;
};

}  // namespace

void check_obj_statements(const std::filesystem::path& path) {
  const std::string text = read_regular_file(path, "OBJ file", kMaxTextFileBytes);
  ObjChecker checker(path);
  // Lines as tinyobjloader splits them: at "\n", "\r\n" and a lone "\r" (a `vw` after a lone
  // "\r" was a statement to it and none to a split at "\n" only: docs/fuzzing.md, finding 19).
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string::npos) end = text.size();
    std::istringstream tokens(text.substr(start, end - start));
    checker.statement(++line_number, tokens);
    start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
  checker.finish();
}

}  // namespace glintlab
