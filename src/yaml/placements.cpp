#include "yaml/placements.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

#include "text/closest_match.h"
#include "text/input_error.h"
#include "text/text_input.h"

namespace fh {

namespace {

const std::vector<std::string> kColumns = {"tx", "ty", "tz", "scale", "axis_x", "axis_y", "axis_z", "degrees"};
enum Column { tx, ty, tz, scale, axis_x, axis_y, axis_z, degrees };

// One line of the file cut at commas, each field with its 1-based column.
struct Field {
    std::string_view text;
    int column;
};
std::vector<Field> split(std::string_view line) {
    std::vector<Field> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = line.find(',', start);
        std::string_view f = line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        int column = int(start) + 1;
        while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1), ++column;
        while (!f.empty() && (f.back() == ' ' || f.back() == '\t' || f.back() == '\r')) f.remove_suffix(1);
        out.push_back({f, column});
        if (comma == std::string_view::npos) return out;
        start = comma + 1;
    }
}

class Table {
public:
    Table(const std::string& text, std::string file) : text_(text), file_(std::move(file)) {}

    Placements read() {
        Placements rows;
        bool header = true;
        // A byte order mark, as spreadsheets write: not part of the header.
        const size_t start = text_.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
        for (size_t at = start; at < text_.size();) {
            // Lines end in LF, CR LF, or a lone CR (a spreadsheet's "CSV (Macintosh)").
            size_t end = text_.find_first_of("\r\n", at);
            if (end == std::string::npos) end = text_.size();
            ++line_;
            const std::string_view line(text_.data() + at, end - at);
            at = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
            if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;  // blank
            if (header) {
                read_header(line);
                header = false;
                continue;
            }
            if (rows.rows.size() == kMaxInstances)
                throw InputError(file_, line_, 1, "more than " + std::to_string(kMaxInstances) +
                                                      " placements (the limit: about 4.5 GB to load and prepare)");
            rows.rows.push_back(read_row(line));
            rows.lines.push_back(line_);
        }
        if (header) throw InputError(file_, "empty placements file: expected a header row such as 'tx,ty,tz'");
        return rows;
    }

private:
    void read_header(std::string_view line) {
        const std::vector<Field> fields = split(line);
        for (size_t i = 0; i < fields.size(); ++i) {
            const std::string name(fields[i].text);
            const auto it = std::find(kColumns.begin(), kColumns.end(), name);
            if (it == kColumns.end()) {
                const std::string hint = closest_match(name, kColumns);
                fail(fields[i].column, "unknown column '" + name + "'" +
                                           (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                                           "; the columns are tx, ty, tz, scale, axis_x, axis_y, axis_z, degrees");
            }
            const size_t c = size_t(it - kColumns.begin());
            if (where_[c] >= 0) fail(fields[i].column, "column '" + name + "' given twice");
            where_[c] = int(i);
        }
        width_ = fields.size();
        for (int c : {tx, ty, tz})
            if (where_[size_t(c)] < 0) fail(1, "the header has no '" + kColumns[size_t(c)] + "' column (tx, ty and tz are required)");
        const int rotation = (where_[axis_x] >= 0) + (where_[axis_y] >= 0) + (where_[axis_z] >= 0) + (where_[degrees] >= 0);
        if (rotation != 0 && rotation != 4)
            fail(1, "a rotation needs all four columns axis_x, axis_y, axis_z and degrees");
    }

    Transform read_row(std::string_view line) {
        const std::vector<Field> fields = split(line);
        if (fields.size() != width_)
            fail(fields.size() < width_ ? int(line.size()) + 1 : fields[width_].column,
                 "expected " + std::to_string(width_) + " values as the header names, got " +
                     std::to_string(fields.size()));
        std::array<double, 8> v{};
        for (size_t c = 0; c < kColumns.size(); ++c)
            if (where_[c] >= 0) v[c] = number(fields[size_t(where_[c])], kColumns[c]);
        Transform t;
        t.translate = {v[tx], v[ty], v[tz]};
        if (where_[scale] >= 0) {
            if (v[scale] == 0) fail(fields[size_t(where_[scale])].column, "'scale' must not be 0");
            t.scale = dvec3(v[scale]);
        }
        if (where_[degrees] >= 0) {
            t.axis = {v[axis_x], v[axis_y], v[axis_z]};
            if (t.axis == dvec3(0)) fail(fields[size_t(where_[axis_x])].column, "the rotation axis is zero");
            t.radians = v[degrees] * std::numbers::pi / 180;
        }
        return t;
    }

    // A number as YAML writes one (docs/format.md, section 1): a leading
    // '+' allowed, one past a double's range not finite.
    double number(const Field& f, const std::string& column) const {
        std::string_view text = f.text;
        if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
        double v = 0;
        const char* end = text.data() + text.size();
        const auto r = std::from_chars(text.data(), end, v);
        if (text.empty() || r.ptr != end || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
            fail(f.column, "'" + column + "' must be a number, got '" + std::string(f.text) + "'");
        // Out of range: too large (not finite), or too small (0 or a denormal).
        if (r.ec == std::errc::result_out_of_range) v = std::strtod(std::string(text).c_str(), nullptr);
        if (!std::isfinite(v)) fail(f.column, "'" + column + "' must be finite, got " + std::string(f.text));
        return v;
    }

    [[noreturn]] void fail(int column, const std::string& what) const { throw InputError(file_, line_, column, what); }

    const std::string& text_;
    std::string file_;
    int line_ = 0;
    size_t width_ = 0;
    std::array<int, 8> where_{-1, -1, -1, -1, -1, -1, -1, -1};
};

}  // namespace

Placements parse_placements(const std::string& text, const std::string& file) {
    check_input_text(file, text, kMaxPlacementsBytes);
    return Table(text, file).read();
}

Placements load_placements(const std::string& path) {
    const std::string text = read_input_file(path, kMaxPlacementsBytes);
    return Table(text, path).read();
}

}  // namespace fh
