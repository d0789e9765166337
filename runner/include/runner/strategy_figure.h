#pragma once
/// Lab 6's three-panel figure, after Veach's: one scene rendered with the light strategy alone,
/// the lobe strategy alone and both weighted together (viewer --strategy-figure).

#include "pathlab/light_sample.h"
#include "pathlab/render/render_options.h"

#include <string>
#include <vector>

namespace pathlab {

class RenderScene;

struct StrategyPanel {
    StrategyChoice strategies;
    const char* name;       ///< "light alone", "lobe alone", "both"
    std::vector<float> rgb; ///< the mean image, linear RGB
    double noise = 0;       ///< its imageNoise, as the viewer's line prints it
    double mean = 0;        ///< its mean radiance over pixels and channels
};

/// The three renders of `scene` with `options`' lab, size, seed and spp, one per strategy choice.
std::vector<StrategyPanel> renderStrategyPanels(const RenderOptions& options,
                                                const RenderScene& scene);

/// The panels side by side, left to right, into a PNG (or any image file writeImage takes).
void writeStrategyFigure(const std::string& path, const std::vector<StrategyPanel>& panels,
                         int width, int height);

/// One line per panel: its name, mean and noise figure; which is the quietest; and a warning
/// where the means part by more than noise explains (weights that do not add up to one).
std::string describeStrategyPanels(const std::vector<StrategyPanel>& panels);

} // namespace pathlab
