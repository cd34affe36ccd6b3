#include "scene/scene.h"

#include <algorithm>

namespace fh {

namespace {
template <typename Light>
void keep(std::vector<Light>& lights, const std::vector<std::string>& names) {
    for (Light& l : lights) l.on = std::find(names.begin(), names.end(), l.name) != names.end();
}
}  // namespace

void keep_only_lights(Scene& scene, const std::vector<std::string>& names) {
    keep(scene.ambient_lights, names);
    keep(scene.directional_lights, names);
    keep(scene.spot_lights, names);
}

}  // namespace fh
