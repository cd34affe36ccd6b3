// Material (report 3, Table 1): a colour and a strength for each of the
// ambient, diffuse and specular terms, a Phong exponent, and glazing.
#pragma once

#include "core/vec.h"

namespace fh {

template <typename T>
struct Material {
    Color<T> ambient_color{0};
    Color<T> diffuse_color{0};
    Color<T> specular_color{0};
    T ambient = 0;
    T diffuse = 0;
    T specular = 0;
    T phong_exponent = 1;
    bool glazed = false;
    T reflectivity = 0;  // weight of the reflected colour when glazed
};

}  // namespace fh
