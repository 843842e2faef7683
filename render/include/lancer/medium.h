// Participating media as integrators see them: POV-Ray's `media` of one
// object's interior, or of the scene (the atmosphere), compiled to world
// space (docs/scene-language.md, "Media"; docs/integrators.md says how each
// integrator traces them).
//
// Along a ray inside a medium, per unit length (POV's units: the scene's),
//   radiance gains    emission + scattering * (light scattered towards the ray)
//   radiance loses    extinction * radiance,  extinction = absorption + sc_ext * scattering
// with every coefficient multiplied by the medium's density at the point
// (the product of its `density` pigments' rgb). A medium holds several
// POV media at once (one interior may list many): their coefficients add.
//
// Phase functions: POV-Ray weighs the light a medium scatters towards the
// viewer by k(cos) (media.cpp), k = 1 for isotropic scattering, where cos
// is the cosine between the direction towards the light and the ray's
// direction (1: looking into the light, forward scattering). POV's k of the
// other types is not normalised (its integral over the sphere is not 4 pi),
// and POV averages k over the media present, whatever each one scatters.
// The classic integrators use POV's k as it is (pov_phase); `path` uses the
// same shapes each normalised to a probability density over the sphere
// (phase_density), so its media conserve energy.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/hit.h"
#include "lancer/texture.h"

namespace lancer {

enum class PhaseType { Isotropic = 1, MieHazy = 2, MieMurky = 3, Rayleigh = 4, HenyeyGreenstein = 5 };

// POV-Ray's k(cos) for one scattering type (see above).
float pov_phase_weight(PhaseType type, float eccentricity, float cos_theta);
// The same shape normalised: a density over the unit sphere (integral 1).
float phase_density(PhaseType type, float eccentricity, float cos_theta);

// One POV media block.
struct MediumComponent {
    Color emission{0.0f};
    Color absorption{0.0f};
    Color scattering{0.0f};
    Color extinction{0.0f};  // absorption + sc_ext * scattering
    PhaseType phase = PhaseType::Isotropic;
    float eccentricity = 0.0f;
    std::vector<const Texture*> densities;  // multiplied; owned by the scene
    Color density_bound{1.0f};              // per channel, no density exceeds it (product over densities)
};

// POV's sampling settings (method 3: adaptive), taken from the media with
// the most intervals, as POV takes them.
struct MediumSampling {
    int method = 3;
    int intervals = 1;
    int samples_min = 10;
    int samples_max = 10;
    int aa_level = 3;
    float aa_threshold = 0.1f;  // the smallest over the media, as POV
    float jitter = 0.0f;
    float ratio = 0.9f;
};

// The coefficients at one point (densities applied, media summed).
struct MediumPoint {
    Color emission{0.0f};
    Color extinction{0.0f};
    Color scattering{0.0f};
};

class Medium {
  public:
    Medium(std::vector<MediumComponent> components, const MediumSampling& sampling);

    const std::vector<MediumComponent>& components() const { return m_components; }
    const MediumSampling& sampling() const { return m_sampling; }
    // No density anywhere: the coefficients are the same at every point.
    bool homogeneous() const { return m_homogeneous; }
    bool emits() const { return m_emits; }
    bool scatters() const { return m_scatters; }
    bool attenuates() const { return m_attenuates; }

    // Coefficients at world point p. `space` is the object id whose texture
    // space the densities are evaluated in: the hit object's for an
    // interior, atmosphere_space() for the scene's medium.
    MediumPoint at(const Vec3& p, std::uint32_t space) const;
    // at() for a homogeneous medium (any point).
    const MediumPoint& constant() const { return m_constant; }
    // Per channel, an upper bound of the extinction (resp. emission) anywhere.
    const Color& extinction_bound() const { return m_extinction_bound; }

    // POV's k averaged over the media (classic integrators).
    float pov_phase(float cos_theta) const;
    // The normalised phase density, averaged over the media as POV averages k.
    float phase_pdf(float cos_theta) const;
    // A direction scattered from a ray travelling along `direction`, drawn
    // from phase_pdf (a medium picked by u.x's first share, then its phase).
    Vec3 sample_phase(const Vec3& direction, float u_choice, const Vec2& u) const;

  private:
    std::vector<MediumComponent> m_components;
    MediumSampling m_sampling;
    MediumPoint m_constant;
    Color m_extinction_bound{0.0f};
    bool m_homogeneous = true;
    bool m_emits = false;
    bool m_scatters = false;
    bool m_attenuates = false;
};

// Where a ray segment runs: in an object's interior medium or the
// atmosphere (with the space its densities use), or in no medium.
struct MediumRegion {
    const Medium* medium = nullptr;
    std::uint32_t space = 0;
    explicit operator bool() const { return medium != nullptr; }
};

}  // namespace lancer
