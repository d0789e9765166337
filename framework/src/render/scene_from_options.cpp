#include "pathlab/render/scene_from_options.h"

#include "pathlab/scene_io/obj_loader.h"
#include "pathlab/scene_io/scene_defaults.h"
#include "pathlab/support/input_error.h"

#include <cstdio>

namespace pathlab {

namespace {

/// The options' camera, with what they leave open framed on the scene's model, and a note
/// saying so.
CameraSettings sceneCamera(const RenderOptions& options, const Scene& scene) {
    if (options.cameraPositionSet && options.cameraLookAtSet) return options.camera;
    const GivenCamera given{options.camera, options.cameraPositionSet, options.cameraLookAtSet,
                            options.fovSet, options.viewDirection};
    const CameraSettings camera = framingCamera(
        scene, given, static_cast<float>(options.width) / static_cast<float>(options.height));
    const Vec3& at = camera.lookAt;
    const Vec3& from = camera.position;
    if (given.lookAt)
        std::fprintf(stderr,
                     "note: no --vp given: looking at (%g, %g, %g) from (%g, %g, %g), far enough "
                     "back to see the whole model; set --vp X Y Z to choose\n",
                     at.x, at.y, at.z, from.x, from.y, from.z);
    else if (given.position)
        std::fprintf(stderr,
                     "note: no --vi given: looking at the model's centre (%g, %g, %g) from (%g, "
                     "%g, %g); set --vi X Y Z to choose\n",
                     at.x, at.y, at.z, from.x, from.y, from.z);
    else if (given.viewDirection)
        std::fprintf(stderr,
                     "note: no --vp given: looking along --vd at the model (%g, %g, %g) from "
                     "(%g, %g, %g), far enough back to see all of it; set --vp X Y Z to "
                     "choose\n",
                     at.x, at.y, at.z, from.x, from.y, from.z);
    else
        std::fprintf(stderr,
                     "note: no camera given (--vp/--vi): looking at the model (%g, %g, "
                     "%g) from (%g, %g, %g); set --vp X Y Z --vi X Y Z to choose\n",
                     at.x, at.y, at.z, from.x, from.y, from.z);
    return camera;
}

} // namespace

Scene loadScene(const RenderOptions& options) {
    if (options.objFiles.empty())
        throw InputError("no scene given: use -c FILE.ecs or -i FILE.obj");
    Scene scene;
    for (const std::string& obj : options.objFiles) loadObj(obj, scene);
    if (options.glossyExponent > 0) {
        bool glossy = false;
        for (Material& m : scene.materials)
            if (m.Ns > 0) {
                m.Ns = options.glossyExponent;
                glossy = true;
            }
        if (!glossy)
            std::fprintf(stderr, "warning: --glossy-exponent changes nothing here: the scene "
                                 "has no glossy material (MTL illum 2 with Ns)\n");
    }
    for (const PointLight& light : options.pointLights) scene.pointLights.push_back(light);
    for (const DirectionalLight& light : options.directionalLights)
        scene.directionalLights.push_back(light);
    scene.camera = sceneCamera(options, scene);
    if (!hasLight(scene)) {
        const PointLight light = headlight(*scene.camera);
        std::fprintf(stderr,
                     "note: the scene has no light (no Ke material, no --pointlight, no "
                     "--dirlight): added a point light of %g W/sr at the camera; give "
                     "--pointlight X Y Z R G B or --dirlight DX DY DZ R G B instead\n",
                     light.intensity.r);
        scene.pointLights.push_back(light);
    }
    return scene;
}

} // namespace pathlab
