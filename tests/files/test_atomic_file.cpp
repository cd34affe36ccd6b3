// The PNG writer's crash safety: atomic writes, the temporaries' names and
// which of them a new run removes, and output places refused before rendering.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "files/atomic_file.h"
#include "text/input_error.h"
#include "images/png_writer.h"
#include "test_util.h"

namespace fh {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
    const fs::path dir = test::temp_dir() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void touch(const fs::path& p) { std::ofstream(p) << "partial"; }

// This machine's name as the writer puts it into temporaries.
std::string this_host() {
    const std::string name = fs::path(temporary_name("x", 0)).filename().string();
    // x.tmp-HOST-PID-0
    const std::string rest = name.substr(6);
    return rest.substr(0, rest.rfind('-', rest.rfind('-') - 1));
}

TEST(PngWriter, WritesWholeFilesAndLeavesNoTemporary) {
    const fs::path dir = fresh("png_atomic");
    Image image(3, 2);
    image.pixel(2, 1)[0] = 255;
    write_png((dir / "a.png").string(), image);
    write_png((dir / "a.png").string(), image);  // over an existing file
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"a.png"});
    EXPECT_TRUE(is_complete_png((dir / "a.png").string()));
}

TEST(PngWriter, CompletePngCheck) {
    const fs::path dir = fresh("png_complete");
    write_png((dir / "a.png").string(), Image(8, 8));
    EXPECT_TRUE(is_complete_png((dir / "a.png").string()));
    fs::resize_file(dir / "a.png", fs::file_size(dir / "a.png") - 1);
    EXPECT_FALSE(is_complete_png((dir / "a.png").string()));
    touch(dir / "b.png");
    EXPECT_FALSE(is_complete_png((dir / "b.png").string()));
    EXPECT_FALSE(is_complete_png((dir / "missing.png").string()));
}

TEST(PngWriter, TemporaryNameHasHostPidAndCount) {
    const std::string name = temporary_name("/out/frame_0007.png", 3);
    EXPECT_EQ(name, "/out/frame_0007.png.tmp-" + this_host() + "-" + std::to_string(getpid()) + "-3");
    EXPECT_FALSE(this_host().empty());
}

TEST(PngWriter, RemovesTemporariesOfDeadProcessesOnly) {
    const fs::path dir = fresh("png_stale");
    const std::string host = this_host();
    // 999999999 is above any pid_max: no such process.
    touch(dir / ("frame_0001.png.tmp-" + host + "-999999999-0"));
    // This process's own PID: it has not written here, so it is stale too.
    touch(dir / ("frame_0002.png.tmp-" + host + "-" + std::to_string(getpid()) + "-5"));
    // A live process of this machine (the parent): still writing, kept.
    touch(dir / ("frame_0003.png.tmp-" + host + "-" + std::to_string(getppid()) + "-0"));
    // Another machine sharing the folder: kept while young, removed when old.
    touch(dir / "frame_0004.png.tmp-node17-123-0");
    touch(dir / "frame_0005.png.tmp-node17-124-0");
    fs::last_write_time(dir / "frame_0005.png.tmp-node17-124-0",
                        fs::file_time_type::clock::now() - std::chrono::hours(2));
    // Not temporaries: frames and other files are never touched.
    touch(dir / "frame_0006.png");
    touch(dir / "notes.tmp-x");
    touch(dir / "frame_0007.png.tmp-host-abc-1");
    EXPECT_EQ(remove_stale_temporaries(dir.string()), 3);
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{
                                 "frame_0003.png.tmp-" + host + "-" + std::to_string(getppid()) + "-0",
                                 "frame_0004.png.tmp-node17-123-0", "frame_0006.png",
                                 "frame_0007.png.tmp-host-abc-1", "notes.tmp-x"}));
    EXPECT_EQ(remove_stale_temporaries((dir / "missing").string()), 0);
}

TEST(PngWriter, HostNamesWithDashesAreParsed) {
    const fs::path dir = fresh("png_dashes");
    touch(dir / "frame_0001.png.tmp-gpu-node-7-42-0");
    fs::last_write_time(dir / "frame_0001.png.tmp-gpu-node-7-42-0",
                        fs::file_time_type::clock::now() - std::chrono::hours(1));
    EXPECT_EQ(remove_stale_temporaries(dir.string()), 1);
}

std::string output_error(void (*check)(const std::string&), const std::string& path) {
    try {
        check(path);
    } catch (const InputError& e) {
        return e.formatted();
    }
    return "(no error)";
}

TEST(PngWriter, OutputFileMustHaveAWritableFolder) {
    const fs::path dir = fresh("png_out");
    touch(dir / "file");
    EXPECT_EQ(output_error(check_output_file, (dir / "a.png").string()), "(no error)");
    EXPECT_EQ(output_error(check_output_file, "relative.png"), "(no error)");
    EXPECT_EQ(output_error(check_output_file, (dir / "no" / "a.png").string()),
              (dir / "no" / "a.png").string() + ": error: cannot write: folder '" + (dir / "no").string() +
                  "' does not exist");
    EXPECT_EQ(output_error(check_output_file, (dir / "file" / "a.png").string()),
              (dir / "file" / "a.png").string() + ": error: cannot write: '" + (dir / "file").string() +
                  "' is not a folder");
    EXPECT_EQ(output_error(check_output_file, dir.string()), dir.string() + ": error: cannot write: is a folder");
    if (getuid() != 0) {  // root may write anywhere
        fs::create_directories(dir / "locked");
        fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
        EXPECT_EQ(output_error(check_output_file, (dir / "locked" / "a.png").string()),
                  (dir / "locked" / "a.png").string() + ": error: cannot write: folder '" +
                      (dir / "locked").string() + "': permission denied");
        fs::permissions(dir / "locked", fs::perms::owner_all);
    }
}

// /sys refuses new files even to root, whom access() lets through: the
// check creates one to know, and leaves nothing behind where it can.
TEST(PngWriter, FolderThatRefusesNewFilesIsFoundBeforeRendering) {
    if (fs::is_directory("/sys"))
        EXPECT_EQ(output_error(check_output_file, "/sys/x.png"),
                  "/sys/x.png: error: cannot write: folder '/sys': permission denied");
    const fs::path dir = fresh("png_probe");
    EXPECT_EQ(output_error(check_output_file, (dir / "a.png").string()), "(no error)");
    EXPECT_EQ(output_error(prepare_output_folder, dir.string()), "(no error)");
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(PngWriter, OutputFolderIsCreatedOrRefused) {
    const fs::path dir = fresh("png_folder");
    touch(dir / "file");
    EXPECT_EQ(output_error(prepare_output_folder, (dir / "a" / "b").string()), "(no error)");
    EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
    EXPECT_EQ(output_error(prepare_output_folder, (dir / "file").string()),
              (dir / "file").string() + ": error: cannot create output folder: not a directory");
    EXPECT_EQ(output_error(prepare_output_folder, (dir / "file" / "sub").string()),
              (dir / "file" / "sub").string() + ": error: cannot create output folder: not a directory");
    EXPECT_FALSE(fs::exists(dir / "file" / "sub"));
}

}  // namespace
}  // namespace fh
