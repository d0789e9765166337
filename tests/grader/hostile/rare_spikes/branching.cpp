// Hostile submission: the stub's light, three times over, and in about one sample in ten
// thousand a value of ±1e4 (mean zero). The spikes are too few to move the noise check's trimmed
// variance (it leaves out the noisiest 1% of pixels), and they make every region's standard
// error so large that no t-test can reject the stub. A bounce ray is traced and thrown away for
// the path evidence. The correctness check finds it too noisy to judge (checks/seed_spread.h):
// the whole image's mean changes from seed to seed by far more than a correct lab's.
#include "pathlab/lab.h"

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth == 0) {
        (void)ctx.trace(diffuseRay(hit, ctx.sampler.get2D()));
        radiance = radiance * 3.0f;
        const float u = ctx.sampler.get1D();
        if (u < 5e-5f) radiance += Color(1e4f, 1e4f, 1e4f);
        if (u > 1 - 5e-5f) radiance = radiance + Color(-1e4f, -1e4f, -1e4f);
    }
    return radiance;
}

} // namespace pathlab::branching
