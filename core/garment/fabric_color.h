#pragma once
// The colour each fabric preset is shown in (the editor, renders, exports).

#include <string>

#include <glm/glm.hpp>

namespace mq {

// cotton, silk, denim, wool, leather, velvet, satin, rib-knit; unknown names
// get cotton's off-white.
glm::vec3 fabricColor(const std::string& fabric);

}  // namespace mq
