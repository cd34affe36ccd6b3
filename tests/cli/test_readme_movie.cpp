// The "Make your own movie" section of docs/guide.md, followed literally: its
// YAML blocks saved under the names their first comment gives, its shell
// block run line by line in a fresh folder (build/firsthit and scripts/ being
// this build's), and the results checked with ffprobe.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "cli/run_command.h"
#include "images/png_writer.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

struct Block {
    std::string language;
    std::string text;
};

// The fenced code blocks of the section `title` of the markdown file `doc`.
std::vector<Block> section_blocks(const std::string& doc, const std::string& title) {
    const std::string markdown = slurp(source_path(doc));
    const size_t start = markdown.find("\n## " + title + "\n");
    if (start == std::string::npos) return {};
    const std::string section = markdown.substr(start, markdown.find("\n## ", start + 1) - start);
    std::vector<Block> blocks;
    const std::regex fence("```([a-z]*)\n([^`]*)```");
    for (std::sregex_iterator it(section.begin(), section.end(), fence), end; it != end; ++it)
        blocks.push_back({(*it)[1], (*it)[2]});
    return blocks;
}

std::string ffprobe(const fs::path& video, const std::string& entries) {
    return run_shell("ffprobe -v error -select_streams v:0 -count_frames -show_entries " + entries +
                     " -of default=nw=1 '" + video.string() + "'")
        .out;
}

TEST(GuideMovie, TheSectionWorksAsWritten) {
    const std::vector<Block> blocks = section_blocks("docs/guide.md", "Make your own movie");
    ASSERT_EQ(blocks.size(), 3u) << "expected the scene, the movie and the commands";
    const fs::path dir = fresh_dir("guide_movie");
    for (const Block& b : blocks) {
        if (b.language != "yaml") continue;
        std::smatch name;  // "# my_scene.yaml: ..."
        ASSERT_TRUE(std::regex_search(b.text, name, std::regex("^# ([a-z_]+\\.yaml)"))) << b.text;
        std::ofstream(dir / name[1].str()) << b.text;
    }
    ASSERT_EQ(blocks[2].language, "sh");
    const fs::path firsthit(FIRSTHIT_BINARY);
    std::istringstream lines(blocks[2].text);
    std::vector<std::string> errs;
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::string command = std::regex_replace(line, std::regex("^build/firsthit "), firsthit.string() + " ");
        command = std::regex_replace(command, std::regex("^scripts/"), source_path("scripts") + "/");
        const auto r = run_shell("cd '" + dir.string() + "' && FIRSTHIT=" + firsthit.string() + " " + command);
        ASSERT_EQ(r.status, 0) << line << "\n" << r.err;
        errs.push_back(r.err);
    }
    // The preview is small, the frames are the movie's, the videos play them.
    EXPECT_EQ(png_size((dir / "preview.png").string()), std::pair(160, 120));
    EXPECT_EQ(png_size((dir / "my_frames/frame_0023.png").string()), std::pair(640, 360));
    EXPECT_FALSE(fs::exists(dir / "my_frames/frame_0024.png"));
    EXPECT_EQ(ffprobe(dir / "my_movie.mp4", "stream=codec_name,width,height,r_frame_rate,nb_read_frames"),
              "codec_name=h264\nwidth=640\nheight=360\nr_frame_rate=12/1\nnb_read_frames=24\n");
    EXPECT_EQ(ffprobe(dir / "my_movie.gif", "stream=codec_name,width,height,nb_read_frames"),
              "codec_name=gif\nwidth=640\nheight=360\nnb_read_frames=24\n");
    // The GIF's frames last 1/12 s (its time base is 1/100 s: 8 or 9 ticks).
    const std::string duration = ffprobe(dir / "my_movie.gif", "format=duration");
    ASSERT_EQ(duration.rfind("duration=", 0), 0u) << duration;
    EXPECT_NEAR(std::stod(duration.substr(9)), 2.0, 0.05);
    // No warning anywhere: the fps came from the frames' movie file.
    for (const std::string& err : errs) EXPECT_EQ(err.find("warning"), std::string::npos) << err;
}

}  // namespace
}  // namespace fh::test
