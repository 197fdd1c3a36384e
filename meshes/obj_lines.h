// A light lexical pre-scan of OBJ and MTL text. tinyobjloader is tolerant (it reads "nan" or
// "1x" as 0, skips unknown keywords) and reports no line numbers for most problems, so before
// handing the text to it we check every statement ourselves and remember the line of every
// `v` and `f` statement and of every material's Kd and Ke: the loader maps tinyobjloader's
// k-th vertex and face back to them to report `file:line` errors.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// One `f` statement, in file order.
struct FaceStatement {
    int line = 0;          // 1-based line of the `f` statement
    int vertex_count = 0;  // always 3 or 4 after a successful scan
    std::string usemtl;    // name of the `usemtl` in effect ("" before the first one)
};

// One `mtllib` statement: the material library files it names, as written.
struct MtllibStatement {
    int line = 0;
    std::vector<std::string> files;
};

struct ObjLines {
    std::vector<int> vertex_lines;     // line of the k-th `v` statement
    std::vector<FaceStatement> faces;  // the `f` statements, in file order
    std::vector<MtllibStatement> mtllibs;
};

// Where a material of an MTL file was defined; 0 = statement absent.
struct MtlMaterialLines {
    std::string file;  // the MTL path used in messages
    int newmtl_line = 0;
    int kd_line = 0;
    int ke_line = 0;
};
using MtlLines = std::map<std::string, MtlMaterialLines>;  // by material name

// Calls visit(line_number, line) for every line of text, splitting at "\n", "\r\n" and a lone
// "\r" exactly as tinyobjloader does, so that both count the same lines.
void for_each_line(std::string_view text, const std::function<void(int, std::string_view)>& visit);

// Splits a line at spaces and tabs (the only separators tinyobjloader knows).
std::vector<std::string_view> split_tokens(std::string_view line);

// Scans OBJ text; throws InputError "path:line: message" on the first bad statement: unknown
// keyword, unparsable or non-finite number, bad vertex index, polygon with fewer than 3 or more
// than 4 vertices.
ObjLines scan_obj(std::string_view text, const std::string& path);

// Scans MTL text and adds its materials to `lines` (the first definition of a name wins, as in
// tinyobjloader); throws InputError on a Kd/Ke statement that is not three finite numbers.
void scan_mtl(std::string_view text, const std::string& path, MtlLines& lines);

}  // namespace hmcr
