#pragma once
// The precomputed tables by id. Adding one: write tables/<id>_table.cpp defining its Table
// and add it to the list in registry.cpp; methods name it in MethodDescriptor::tables.
#include <string>
#include <vector>

#include "core/gpu_contract.hpp"
#include "gl/shader_library.hpp"
#include "tables/table.hpp"

namespace glintlab {

/// Every table, each with its unit.
const std::vector<Table>& all_tables();
/// Throws InputError for an unknown id, listing the known ones.
const Table& find_table(const std::string& id);
/// "TABLE_UNIT_GLINT_DICTIONARY" for "glint-dictionary": the GLSL name of a table's unit.
std::string table_define(const std::string& id);
/// TABLE_UNIT_<ID> = unit for every table, then every table's GLSL constants (each name once):
/// part of every program that may read a table (generated/gpu_contract.glsl).
ShaderDefines table_defines();

}  // namespace glintlab
