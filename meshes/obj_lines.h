// SPDX-License-Identifier: Apache-2.0
// The lexical layer of hmcr's OBJ and MTL readers (docs/design.md §11.2): lines, the tokens of
// a statement, comments and numbers, every problem reported as "file:line: why". A statement's
// tokens are read one at a time, in place, so that a line costs no memory beyond the file's
// text however long it is; lines are nevertheless limited (kMaxObjLineBytes).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hmcr {

// Longer OBJ and MTL lines are refused at their line. The longest statement hmcr reads is a face
// of kMaxPolygonCorners (meshes/triangulate.h) corners written "v/t/n" with 10-digit indices,
// about 0.36 MB; 4 MiB leaves room for any name.
inline constexpr std::size_t kMaxObjLineBytes = std::size_t(4) << 20;

// Calls visit(line_number, line) for every line of text, splitting at "\n", "\r\n" and a lone
// "\r" (1-based numbers, as editors count them).
void for_each_line(std::string_view text, const std::function<void(int, std::string_view)>& visit);

// Splits a line at spaces and tabs.
std::vector<std::string_view> split_tokens(std::string_view line);

// One line of OBJ or MTL: its keyword, then its tokens one at a time. Spaces and tabs separate
// tokens; a token that starts with '#' starts a comment, which runs to the end of the line.
class Statement {
public:
    explicit Statement(std::string_view line);

    // The first token; "" for a line of nothing but separators and a comment.
    std::string_view keyword() const { return m_keyword; }
    // The next token, "" after the last.
    std::string_view next();
    // How many tokens are left (it reads them).
    std::size_t count_rest();
    // The rest of the line up to a comment, without the separators around it: a name, which
    // may hold spaces (`newmtl dark grey`).
    std::string_view rest_trimmed();

private:
    std::string_view m_rest;  // the line after the last token read
    std::string_view m_keyword;
};

// Calls visit(line_number, statement) for every line of OBJ or MTL text that holds a statement,
// after a UTF-8 byte-order mark, lines split as for_each_line does. Throws InputError
// "path:line: why" for a NUL byte or a line longer than kMaxObjLineBytes.
void for_each_statement(std::string_view text, const std::string& path,
                        const std::function<void(int, Statement&)>& visit);

// A finite decimal number ("1", "-2.5", "+1e-3"), read as the double nearest to it. Throws
// InputError "path:line: why" for anything else, NaN and infinities included.
double parse_obj_number(std::string_view token, const std::string& path, int line);

// Throws InputError "path:line: message".
[[noreturn]] void fail_at_line(const std::string& path, int line, const std::string& message);

}  // namespace hmcr
