// SPDX-License-Identifier: Apache-2.0
// Lines, statements and numbers of OBJ and MTL text (obj_lines.h).
#include "meshes/obj_lines.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "common/error.h"
#include "common/text_file.h"

namespace hmcr {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t'; }

std::string_view skip_separators(std::string_view text) {
    std::size_t start = 0;
    while (start < text.size() && is_separator(text[start])) ++start;
    return text.substr(start);
}

}  // namespace

void fail_at_line(const std::string& path, int line, const std::string& message) {
    throw InputError(at(path, line), message);
}

// Plain loops: std::string_view::find_first_of calls memchr on its set for every character,
// which was 6% of loading a 10^6-face OBJ.
void for_each_line(std::string_view text, const std::function<void(int, std::string_view)>& visit) {
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = start;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        visit(++number, text.substr(start, end - start));
        if (end == text.size()) break;
        const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
        start = end + (crlf ? 2 : 1);
    }
}

std::vector<std::string_view> split_tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    for (std::size_t i = 0; i < line.size();) {
        if (is_separator(line[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

Statement::Statement(std::string_view line) : m_rest(line) { m_keyword = next(); }

std::string_view Statement::next() {
    m_rest = skip_separators(m_rest);
    if (m_rest.empty() || m_rest.front() == '#') {
        m_rest = {};
        return {};
    }
    std::size_t end = 0;
    while (end < m_rest.size() && !is_separator(m_rest[end])) ++end;
    const std::string_view token = m_rest.substr(0, end);
    m_rest.remove_prefix(end);
    return token;
}

std::size_t Statement::count_rest() {
    std::size_t n = 0;
    while (!next().empty()) ++n;
    return n;
}

std::string_view Statement::rest_trimmed() {
    const std::string_view start = skip_separators(m_rest);
    std::string_view last;
    for (std::string_view t = next(); !t.empty(); t = next()) last = t;
    if (last.empty()) return {};
    return start.substr(0, std::size_t(last.data() + last.size() - start.data()));
}

void for_each_statement(std::string_view text, const std::string& path,
                        const std::function<void(int, Statement&)>& visit) {
    for_each_line(without_bom(text), [&](int number, std::string_view line) {
        if (line.size() > kMaxObjLineBytes) {
            fail_at_line(path, number,
                         fmt::format("a line of {} bytes: hmcr reads lines of at most {}",
                                     line.size(), kMaxObjLineBytes));
        }
        if (line.find('\0') != std::string_view::npos) {
            fail_at_line(path, number, "binary data (NUL byte) in a text file");
        }
        Statement statement(line);
        if (!statement.keyword().empty()) visit(number, statement);
    });
}

// A leading '+' is valid OBJ but not from_chars syntax.
double parse_obj_number(std::string_view token, const std::string& path, int line) {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const char* end = digits.data() + digits.size();
    auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
    if (digits.size() < token.size() && (digits.empty() || digits.front() == '-')) {
        ec = std::errc::invalid_argument;  // "+-1"
    }
    if (ec == std::errc::result_out_of_range) {
        fail_at_line(path, line, fmt::format("number {} is out of range", quote(token)));
    }
    if (ec != std::errc{} || ptr != end) {
        fail_at_line(path, line, fmt::format("cannot parse number {}", quote(token)));
    }
    if (!std::isfinite(value)) {
        fail_at_line(path, line, fmt::format("{} is not a finite number", quote(token)));
    }
    return value;
}

}  // namespace hmcr
