// Arbitrary output variables: layers a render writes beside the beauty, in
// the same EXR (`lancer render --aov albedo,normal,depth`), as compositors
// and denoisers read them. Each layer is a deterministic image of the
// camera rays, rendered in its own short pass over the same pixels and the
// same sub-pixel positions the beauty's samples use, so it lines up with
// the beauty whatever integrator made it and however the render ended
// (time budget, noise target, interrupt, resume).
//
//   albedo    albedo.R/G/B  the denoiser albedo (lancer/shading/denoiser_guides.h)
//   normal    N.X/Y/Z       the denoiser normal, world space, in [-1, 1]
//   depth     Z             distance along the camera ray to the first hit;
//                           +inf where no sample of the pixel hit anything
//   position  P.X/Y/Z       world position of the first hit (0 where none)
//   alpha     A             POV-Ray's +UA alpha (camera_alpha)
#pragma once

#include <string>
#include <vector>

#include "lancer/host/image_io.h"
#include "lancer/host/renderer.h"

namespace lancer {

enum class Aov { Albedo, Normal, Depth, Position, Alpha };

// "albedo", "normal", ...
const char* aov_name(Aov aov);
// Every layer, in the order the names above list them.
const std::vector<Aov>& all_aovs();

// A comma-separated list of layer names, each at most once; on error an
// empty list and `problem` says which name is wrong and what is known.
std::vector<Aov> parse_aov_list(const std::string& text, std::string& problem);

// Renders each requested layer over `options`' image size and crop window,
// `samples` samples per pixel. Ignores the options' budget, noise target, checkpoints,
// progress and cancel flag: these passes are short and always complete.
// The beauty's integrator chooses the sampler and whether one sample goes
// through the pixel centre, so sample k of a layer looks where sample k of
// the beauty looked.
std::vector<ImageLayer> render_aovs(const RenderScene& scene, const Integrator& beauty, const std::vector<Aov>& layers,
                                    const RenderOptions& options, int samples);

// The samples per pixel AOV passes take beside a beauty that took
// `beauty_mean_samples` on average: as many, at most 16.
int aov_samples_for(double beauty_mean_samples);

}  // namespace lancer
