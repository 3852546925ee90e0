#pragma once
// Strict, typed access to one TOML table of a scene file. Every getter validates type and range;
// finish() rejects keys nobody asked for. Messages name the file, line, key, value and what is
// allowed, and are thrown as InputError.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace glintlab {

/// "0.005 .. 0.7": a range as every message (and the generated docs) write it.
std::string range_text(double min, double max);
/// A number as the messages write it (6 significant digits).
std::string number_text(double value);

class TomlReader {
 public:
  TomlReader(const toml::table& table, std::string file, std::string context);

  [[nodiscard]] bool has(const std::string& key) const;
  std::string get_string(const std::string& key, const std::string& fallback,
                         const std::vector<std::string>& allowed = {});
  std::string require_string(const std::string& key, const std::vector<std::string>& allowed = {});
  double get_number(const std::string& key, double fallback, double min, double max);
  double require_number(const std::string& key, double min, double max);
  int get_int(const std::string& key, int fallback, int min, int max);
  bool get_bool(const std::string& key, bool fallback);
  glm::vec3 get_vec3(const std::string& key, glm::vec3 fallback);
  glm::vec3 require_vec3(const std::string& key);
  /// A scalar (grey) or [r, g, b]; every component in [min, max].
  glm::vec3 get_colour(const std::string& key, glm::vec3 fallback, double min, double max);
  /// A scalar (both) or [x, y]; every component in [min, max].
  glm::vec2 get_vec2(const std::string& key, glm::vec2 fallback, double min, double max);
  std::vector<glm::vec3> require_vec3_list(const std::string& key, std::size_t min_count);
  /// A sub-table (key = {...} or [key]); nullptr when absent.
  const toml::table* get_table(const std::string& key);
  /// An array of tables ([[key]] or key = [{...}]); empty when absent.
  std::vector<const toml::table*> get_table_array(const std::string& key);

  /// Marks keys as known without reading them (keys read only in some branches).
  void allow(std::initializer_list<const char*> keys) { for (const char* k : keys) used_.insert(k); }

  /// Throws for any key of the table that no getter asked for.
  void finish() const;

  /// "file:line: context key 'k'": the prefix of every message about `key`.
  [[nodiscard]] std::string where(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& context() const { return context_; }

 private:
  const toml::node* lookup(const std::string& key);
  double as_number(const std::string& key, const toml::node& node, double min, double max) const;

  const toml::table& table_;
  std::string file_;
  std::string context_;
  std::set<std::string> used_;
};

}  // namespace glintlab
