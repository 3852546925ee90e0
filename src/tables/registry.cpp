#include "tables/registry.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/error.hpp"

namespace glintlab {

Table glint_dictionary_table();
Table ltc_ggx_table();
Table ltc_ndf_table();
Table dfg_table();

const std::vector<Table>& all_tables() {
  static const std::vector<Table> tables = [] {
    std::vector<Table> list = {
        glint_dictionary_table(),
        ltc_ggx_table(),
        ltc_ndf_table(),
        dfg_table(),  // last: the tables above keep their units
    };
    for (std::size_t i = 0; i < list.size(); ++i) list[i].unit = kFirstTableUnit + static_cast<int>(i);
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        for (const TableConstant& a : list[i].glsl_constants)
          for (const TableConstant& b : list[j].glsl_constants)
            if (a.name == b.name && a.glsl_value() != b.glsl_value())
              throw std::logic_error("tables '" + list[j].source.id + "' and '" + list[i].source.id +
                                     "' both declare the GLSL constant " + a.name + ", as " + b.glsl_value() + " and " +
                                     a.glsl_value() + "; one name, one value");
    return list;
  }();
  return tables;
}

const Table& find_table(const std::string& id) {
  for (const auto& t : all_tables())
    if (t.source.id == id) return t;
  std::string known;
  for (const auto& t : all_tables()) known += (known.empty() ? "" : ", ") + t.source.id;
  throw InputError("unknown precomputed table '" + id + "'; allowed: " + known);
}

std::string table_define(const std::string& id) {
  std::string name = "TABLE_UNIT_";
  for (char c : id) name += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
  return name;
}

ShaderDefines table_defines() {
  ShaderDefines defines;
  for (const auto& t : all_tables()) defines.emplace_back(table_define(t.source.id), std::to_string(t.unit));
  for (const auto& t : all_tables())
    for (const TableConstant& c : t.glsl_constants) {
      const std::pair<std::string, std::string> define{c.name, c.glsl_value()};
      if (std::find(defines.begin(), defines.end(), define) == defines.end()) defines.push_back(define);
    }
  return defines;
}

}  // namespace glintlab
