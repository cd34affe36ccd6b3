#include "pipeline/frame_files.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

#include "files/atomic_file.h"
#include "text/input_error.h"
#include "images/png_writer.h"

namespace fh {

namespace {

// Where the frame number stands in a file name: [begin, end) and its padding.
struct NumberField {
    size_t begin = 0, end = 0;
    int digits = 0;
};

// %d, %0Nd or a run of #; nullopt when the name has none. Two are an error.
std::optional<NumberField> number_field(const std::string& name, const std::string& out) {
    std::optional<NumberField> found;
    auto add = [&](NumberField f) {
        if (found) throw UsageError("--out '" + out + "' has two frame numbers; give one (%04d or ####)");
        found = f;
    };
    for (size_t i = 0; i < name.size(); ++i) {
        if (name[i] == '#') {
            size_t j = i;
            while (j < name.size() && name[j] == '#') ++j;
            add({i, j, int(j - i)});
            i = j - 1;
        } else if (name[i] == '%') {
            size_t j = i + 1;
            while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
            if (j >= name.size() || name[j] != 'd')
                throw UsageError("--out '" + out + "': '%' stands for the frame number only as %d or %04d");
            const std::string width = name.substr(i + 1, j - i - 1);
            add({i, j + 1, width.empty() ? 1 : std::max(1, std::stoi(width.substr(0, 3)))});
            i = j;
        }
    }
    return found;
}

std::string padded(int n, int digits) {
    std::string s = std::to_string(n);
    if (int(s.size()) < digits) s.insert(0, size_t(digits) - s.size(), '0');
    return s;
}

}  // namespace

FrameFiles parse_frame_files(const std::string& out) {
    if (out.empty()) throw UsageError("--out needs a folder or a file name pattern, e.g. 'shots/take1_%04d.png'");
    const std::filesystem::path path(out);
    const std::string name = path.filename().string();
    FrameFiles files;
    const auto field = number_field(name, out);
    if (path.has_parent_path() && (out.find('#') < out.size() - name.size() || out.find('%') < out.size() - name.size()))
        throw UsageError("--out '" + out + "': the frame number (%04d or ####) goes in the file name, not the folder");
    if (!field) {
        std::string lower = name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ".png") == 0)
            throw UsageError("--out '" + out + "' names one file, but a movie has many frames: put %04d or #### where "
                             "the frame number goes, e.g. '" + (path.parent_path() / (name.substr(0, name.size() - 4) + "_%04d.png")).string() + "'");
        files.folder = path;
        return files;
    }
    files.folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    files.prefix = name.substr(0, field->begin);
    files.suffix = name.substr(field->end);
    files.digits = field->digits;
    std::string ext = files.suffix.size() >= 4 ? files.suffix.substr(files.suffix.size() - 4) : "";
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".png")
        throw UsageError("--out '" + out + "': frames are PNG files (resume and scripts/encode.sh read them); end the "
                         "pattern in .png, e.g. 'shots/take1_%04d.png'");
    return files;
}

// The padding of a frame_count-frame movie's numbers.
int FrameFiles::width(int frame_count) const {
    return digits ? digits : std::max(4, int(std::to_string(frame_count > 0 ? frame_count - 1 : 0).size()));
}

std::string FrameFiles::name(int frame, int frame_count) const {
    return prefix + padded(frame, width(frame_count)) + suffix;
}

std::string FrameFiles::pattern(int frame_count) const {
    return prefix + "%0" + std::to_string(width(frame_count)) + "d" + suffix;
}

int FrameFiles::frame_of(const std::string& file_name) const {
    if (file_name.size() <= prefix.size() + suffix.size() || file_name.rfind(prefix, 0) != 0 ||
        file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return -1;
    const std::string number = file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size());
    if (number.size() > 9 || !std::all_of(number.begin(), number.end(), [](unsigned char c) { return std::isdigit(c); }))
        return -1;
    return std::stoi(number);
}

std::string FramesOrigin::describe() const {
    std::ostringstream s;
    s << movie << ": " << frames << (frames == 1 ? " frame" : " frames") << " at " << fps << " fps, " << width << "x"
      << height;
    if (!render.empty()) s << " (" << render << ")";
    return s.str();
}

std::string FramesOrigin::text() const {
    std::ostringstream s;
    s << "# firsthit frames: the movie these frames belong to (scripts/encode.sh reads it)\n"
      << "movie: " << movie << "\nframes: " << frames << "\nfps: " << fps << "\nwidth: " << width
      << "\nheight: " << height << "\npattern: " << pattern << "\n";
    if (!render.empty()) s << "render: " << render << "\n";
    return s.str();
}

std::optional<FramesOrigin> read_frames_origin(const std::filesystem::path& movie_file) {
    std::ifstream in(movie_file);
    if (!in) return std::nullopt;
    FramesOrigin o;
    std::string line;
    int line_number = 0;
    while (std::getline(in, line)) {
        ++line_number;
        if (line.empty() || line[0] == '#') continue;
        const size_t colon = line.find(": ");
        if (colon == std::string::npos)
            throw InputError(movie_file.string(), line_number, 1, "expected 'key: value'");
        const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
        try {
            if (key == "movie") o.movie = value;
            else if (key == "frames") o.frames = std::stoi(value);
            else if (key == "fps") o.fps = std::stod(value);
            else if (key == "width") o.width = std::stoi(value);
            else if (key == "height") o.height = std::stoi(value);
            else if (key == "pattern") o.pattern = value;
            else if (key == "render") o.render = value;
        } catch (const std::exception&) {
            throw InputError(movie_file.string(), line_number, int(colon + 3), "'" + value + "' is no number");
        }
    }
    return o;
}

int claim_frame_folder(const FrameFiles& files, const FramesOrigin& origin, bool clean) {
    prepare_output_folder(files.folder.string());
    const std::filesystem::path movie_file = files.movie_file();
    const std::optional<FramesOrigin> before = read_frames_origin(movie_file);
    std::vector<std::filesystem::path> frames;
    std::string past_end, other_size;
    for (const auto& entry : std::filesystem::directory_iterator(files.folder)) {
        const int i = files.frame_of(entry.path().filename().string());
        if (i < 0 || !entry.is_regular_file()) continue;
        frames.push_back(entry.path());
        if (i >= origin.frames && (past_end.empty() || entry.path().filename().string() < past_end))
            past_end = entry.path().filename().string();
        if (!before && other_size.empty()) {
            const auto size = png_size(entry.path().string());
            if (size && (size->first != origin.width || size->second != origin.height))
                other_size = entry.path().filename().string() + " is " + std::to_string(size->first) + "x" +
                             std::to_string(size->second);
        }
    }
    // (A movie file from before the render line was written says nothing of it.)
    FramesOrigin compared = origin;
    if (before && before->render.empty()) compared.render.clear();
    const bool other_movie = before && before->text() != compared.text();
    int removed = 0;
    if (clean) {
        for (const auto& f : frames) removed += std::filesystem::remove(f) ? 1 : 0;
        std::filesystem::remove(movie_file);
    } else if (other_movie || !past_end.empty() || !other_size.empty()) {
        const std::string where = (files.folder / (files.prefix + "*" + files.suffix)).string();
        const std::string what = other_movie ? "frames of " + before->describe()
                                 : !past_end.empty() ? "frames past this movie's end (" + past_end + ")"
                                                     : "frames of another size (" + other_size + ")";
        throw UsageError(where + " holds " + what + "; this render is " + origin.describe() +
                         ". Pass --clean to remove the old frames first, or another --out");
    }
    const std::string bytes = origin.text();
    write_file_atomic(movie_file.string(), std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    return removed;
}

}  // namespace fh
