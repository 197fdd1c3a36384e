// A lexical pre-scan of OBJ and MTL text. tinyobjloader is tolerant (it reads "nan" or "1x" as
// 0, skips unknown keywords) and reports no line numbers for most problems, so before handing
// the text to it we check every statement ourselves and remember the line of every `f`
// statement and of every material's Kd and Ke: the loader maps tinyobjloader's k-th face back
// to them to report `file:line` errors.
//
// The scan also cleans the text for tinyobjloader, line for line (so both count the same
// lines): a UTF-8 byte-order mark at the start is dropped, and so is a comment after data
// (`Kd 0.5 0.5 0.5 # grey`), which tinyobjloader would read as more data.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// One `f` statement, in file order.
struct FaceStatement {
    int line = 0;        // 1-based line of the `f` statement
    std::string usemtl;  // name of the `usemtl` in effect ("" before the first one)
};

// One `mtllib` statement: the material library files it names, as written.
struct MtllibStatement {
    int line = 0;
    std::vector<std::string> files;
};

struct ObjLines {
    std::string clean_text;            // the text for tinyobjloader
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
// The same into `tokens` (cleared first), to reuse its storage line after line.
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);

// Scans OBJ text; throws InputError "path:line: message" on the first bad statement: unknown
// keyword, unparsable or non-finite number, a v, vt or vn index out of range, polygon with
// fewer than 3 vertices (more than 4 are triangulated by the repairs, or refused by --strict).
ObjLines scan_obj(std::string_view text, const std::string& path);

// Scans MTL text, adds its materials to `lines` and returns the text for tinyobjloader. Throws
// InputError on a Kd/Ke statement that is not three finite numbers and on a material defined
// twice (in this file or an earlier one); adds a "path:line: ..." warning for every statement
// hmcr does not know (a typo such as `KE` would otherwise silently turn a light off).
std::string scan_mtl(std::string_view text, const std::string& path, MtlLines& lines,
                     std::vector<std::string>& warnings);

}  // namespace hmcr
