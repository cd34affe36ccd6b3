// The error a scene file gives, as the tests compare it: the formatted
// InputError with the file's path shown as FILE.
#pragma once

#include <string>

#include "text/input_error.h"
#include "yaml/scene_loader.h"
#include "test_util.h"

namespace fh::test {

inline std::string error_of_file(const std::string& path) {
    return check_error(path, [](const std::string& p) { load_scene(p); });
}

// The error of `yaml` written to a temporary scene file called `name`.
inline std::string scene_error(const std::string& yaml, const std::string& name = "bad_scene.yaml") {
    return error_of_file(write_temp_file(name, yaml));
}

}  // namespace fh::test
