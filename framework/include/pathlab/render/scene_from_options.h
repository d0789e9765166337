#pragma once
/// The scene a render's options name: their OBJ files loaded, their lights and camera added.

#include "pathlab/render/render_options.h"
#include "pathlab/scene_io/scene.h"

namespace pathlab {

/// Loads the scene files the options name and adds their lights and camera. Where they give no
/// camera, or no light at all, it adds its own with a note on stderr
/// (pathlab/scene_io/scene_defaults.h): a scene from loadScene() always has a camera.
Scene loadScene(const RenderOptions& options);

} // namespace pathlab
