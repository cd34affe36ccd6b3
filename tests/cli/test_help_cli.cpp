// One source of truth for help: every flag of the flag table appears in
// `firsthit --help` and in the command-line section of docs/cli.md (whose
// synopsis is the help's own), every command's help lists each flag it takes, and
// Args::parse takes exactly those.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/flags.h"
#include "cli/run_command.h"
#include "text/input_error.h"

namespace fh::test {
namespace {

// The "## Command line" section of docs/cli.md, up to the next "## ".
std::string docs_command_line() {
    const std::string cli_md = slurp(source_path("docs/cli.md"));
    const size_t start = cli_md.find("\n## Command line\n");
    EXPECT_NE(start, std::string::npos) << "docs/cli.md has no '## Command line' section";
    if (start == std::string::npos) return "";
    return cli_md.substr(start, cli_md.find("\n## ", start + 1) - start);
}

TEST(HelpCli, EveryFlagIsInTheTopLevelHelpAndTheDocs) {
    const auto help = run_firsthit("--help");
    ASSERT_EQ(help.status, 0);
    const std::string docs = docs_command_line();
    for (const Flag& f : all_flags()) {
        for (std::string_view name : {f.name, f.alias}) {
            if (name.empty()) continue;
            EXPECT_NE(help.out.find(std::string(name)), std::string::npos) << name << " is not in firsthit --help";
            EXPECT_NE(docs.find(std::string(name)), std::string::npos) << name << " is not in docs/cli.md";
        }
        EXPECT_NE(help.out.find(std::string(f.help.substr(0, 20))), std::string::npos) << f.name << "'s help text";
    }
    for (const CommandSpec& c : all_commands())
        EXPECT_NE(docs.find("firsthit " + std::string(c.name)), std::string::npos) << c.name;
}

TEST(HelpCli, TheDocsSynopsisIsTheHelpsOwn) {
    const auto help = run_firsthit("--help");
    const std::string usage = help.out.substr(help.out.find("usage:\n") + 7,
                                              help.out.find("\n\ncommands:") - help.out.find("usage:\n") - 7);
    std::string unindented;
    for (size_t at = 0; at < usage.size();) {
        const size_t end = std::min(usage.find('\n', at), usage.size());
        unindented += usage.substr(at + 2, end - at - 2) + "\n";
        at = end + 1;
    }
    EXPECT_NE(docs_command_line().find("```\n" + unindented + "```"), std::string::npos)
        << "docs/cli.md's synopsis differs from firsthit --help's; paste this:\n" << unindented;
}

TEST(HelpCli, EachCommandsHelpListsItsFlagsAndOnlyThose) {
    for (const CommandSpec& c : all_commands()) {
        const auto r = run_firsthit(std::string(c.name) + " --help");
        ASSERT_EQ(r.status, 0) << c.name;
        EXPECT_EQ(r.out.rfind("usage: firsthit " + std::string(c.name), 0), 0u) << r.out;
        for (const Flag& f : all_flags()) {
            const bool takes = std::find(c.flags.begin(), c.flags.end(), f.name) != c.flags.end();
            if (f.name == "--help") continue;
            EXPECT_EQ(r.out.find("  " + std::string(f.alias.empty() ? f.name : f.alias)) != std::string::npos, takes)
                << c.name << " --help and " << f.name;
        }
    }
}

TEST(HelpCli, ParseTakesTheTablesFlagsAndPointsElsewhereForOthers) {
    const CommandSpec& render = *find_command("render");
    const Args a = Args::parse(render, {"scene.yaml", "-o", "x.png", "--resolution=160x120", "--stats"});
    EXPECT_EQ(a.positional(), std::vector<std::string>{"scene.yaml"});
    EXPECT_EQ(a.value("--output"), "x.png");  // under the flag's name, typed as its alias
    EXPECT_EQ(a.value("--resolution"), "160x120");
    EXPECT_TRUE(a.has("--stats"));
    auto message = [&](const std::vector<std::string>& words) {
        try {
            Args::parse(render, words);
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    EXPECT_EQ(message({"f.yaml", "--range", "1-3"}),
              "'render' has no option '--range': render draws one frame; for several use 'firsthit frames MOVIE "
              "--range A-B'");
    EXPECT_EQ(message({"f.yaml", "--width", "100"}),
              "'render' has no option '--width': set the image size with --resolution WxH (e.g. 160x120) or --scale F");
    EXPECT_EQ(message({"f.yaml", "--sppp", "4"}),
              "unknown option '--sppp' for 'render' (did you mean '--spp'?); see 'firsthit render --help'");
    EXPECT_EQ(message({"f.yaml", "--spp"}), "option '--spp' needs a value (N)");
    EXPECT_EQ(message({"f.yaml", "--stats=1"}), "option '--stats' takes no value");
}

TEST(HelpCli, AccuracyHelpExplainsEveryColumn) {
    const std::string dir = fresh_dir("accuracy_columns").string();
    const auto table = run_firsthit("accuracy " + source_path("animations/scene.yaml") +
                                    " --resolution 8x8 --reference-spp 2 --max-spp 2 --runs 1 --csv " + dir + "/a.csv");
    ASSERT_EQ(table.status, 0) << table.err;
    const std::string csv = slurp(dir + "/a.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    const std::string help = run_firsthit("accuracy --help").out;
    size_t columns = 0;
    for (size_t at = 0; at <= header.size(); ++columns) {
        const size_t end = std::min(header.find(',', at), header.size());
        const std::string column = header.substr(at, end - at);
        EXPECT_NE(help.find("  " + column + " "), std::string::npos) << column << " is not explained";
        at = end + 1;
    }
    EXPECT_EQ(columns, 14u);
    EXPECT_NE(help.find("Which setting for which purpose"), std::string::npos);
    // The report's scene has no texture: no mipmaps rows, every row's mipmaps 1.
    EXPECT_EQ(csv.find("\nmipmaps,"), std::string::npos);
    EXPECT_EQ(csv.find(",0\n"), std::string::npos);
}

TEST(HelpCli, AccuracyWeighsMipmapsWhereATextureIsSeenFromAfar) {
    // The checkerboard floor receding to the horizon: one sample with its
    // mipmaps, and one without (--no-mipmaps), each a row; the mipmaps are
    // the more exact against 16 samples.
    const std::string dir = fresh_dir("accuracy_mipmaps").string();
    const auto table = run_firsthit("accuracy " + source_path("animations/gltf/checker_floor.gltf") +
                                    " --resolution 96x54 --reference-spp 16 --max-spp 1 --runs 1 --csv " + dir +
                                    "/a.csv");
    ASSERT_EQ(table.status, 0) << table.err;
    std::istringstream csv(slurp(dir + "/a.csv"));
    std::map<int, double> psnr;  // by the mipmaps column
    for (std::string line; std::getline(csv, line);) {
        if (line.rfind("mipmaps,", 0) != 0) continue;
        std::vector<std::string> cells;
        std::istringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        ASSERT_EQ(cells.size(), 14u) << line;
        EXPECT_EQ(cells[1], "1") << line;  // one sample a pixel
        psnr[std::stoi(cells[13])] = std::stod(cells[8]);
    }
    ASSERT_EQ(psnr.size(), 2u);
    EXPECT_GT(psnr[1], psnr[0] + 3) << "with mipmaps " << psnr[1] << " dB, without " << psnr[0];
    // And a render says it went without them.
    const auto render = run_firsthit("render " + source_path("animations/gltf/checker_floor.gltf") +
                                     " --resolution 32x18 --no-mipmaps --stats -o " + dir + "/f.png");
    ASSERT_EQ(render.status, 0) << render.err;
    EXPECT_NE(render.out.find("mipmaps: off\n"), std::string::npos) << render.out;
}

}  // namespace
}  // namespace fh::test
