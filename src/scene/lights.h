// Ambient and directional lights (report 6.1, 6.2). The spot light, the one
// with real geometry, has its own file.
#pragma once

#include <string>

#include "core/vec.h"

namespace fh {

template <typename T>
struct AmbientLight {
    std::string name;
    Color<T> color{0};
    T intensity = 0;
    bool on = true;  // a movie's `lights:` switches the others off
};

template <typename T>
struct DirectionalLight {
    std::string name;
    Color<T> color{0};
    T intensity = 0;
    Vec3<T> direction{0, 0, -1};  // unit; the way the light travels
    bool on = true;
    int node = -1;  // a glTF light: the scene node that points it (scene/node.h)

    Vec3<T> to_light() const { return -direction; }
};

}  // namespace fh
