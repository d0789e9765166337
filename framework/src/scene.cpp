#include "pathlab/scene.h"

#include "pathlab/bounding_box.h"
#include "pathlab/scene_defaults.h"

namespace pathlab {

CameraSettings Scene::framingCamera() const {
    return pathlab::framingCamera(boundingBoxOf(positions), GivenCamera{}, 1.0f);
}

} // namespace pathlab
