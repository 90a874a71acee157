// Fractal sums of a basis noise: fBm (seed 002's normalizedOctaveNoise3D), Musgrave's ridged
// multifractal and heterogeneous terrain (as Blender; digest 001 §3.18). GLSL twin of
// reference/noise/fractal.hpp (formulas and decisions there): the same float operations in the
// same order, every intermediate precise.
//
// The including shader defines the basis before the include, after the basis's own include:
//   #include "noise/perlin.glsl"
//   #define FRACTAL_BASIS(q) gt_perlin3(q)
//   #include "noise/fractal.glsl"
// The parameters come as a GtFractalTerms, derived on the host in double by
// gt::fractal_terms<float>(FractalParams) (core/params/noise_fractal.hpp), whose layout it mirrors.
// Inputs:  FRACTAL_BASIS(q) (defined by the including shader) and a GtFractalTerms; a point p.
// Outputs: gt_fbm, gt_ridged_multifractal, gt_hetero_terrain at p.
// Twin:    reference/noise/fractal.hpp.
#ifndef GT_NOISE_FRACTAL_GLSL
#define GT_NOISE_FRACTAL_GLSL

#ifndef FRACTAL_BASIS
#error "define FRACTAL_BASIS(q) (a float function of a vec3) before including noise/fractal.glsl"
#endif

struct GtFractalTerms {
  int whole_octaves;        // floor(octaves)
  float remainder;          // octaves − floor(octaves)
  float lacunarity;
  float gain;               // fbm: amplitude ratio; ridged: weight feedback gain
  float spectral_ratio;     // lacunarity^(−H)
  float fbm_normalisation;  // 1 / (Σ_{k<n} gain^k + r·gain^n)
  float offset;
};

float gt_fbm(vec3 p, GtFractalTerms terms) {
#ifdef GT_MUTANT_NOISE_FBM_GPU_OCTAVE_SHIFT
  precise vec3 q = p * terms.lacunarity;  // mutant (this twin alone): every octave one lacunarity too high
#else
  precise vec3 q = p;
#endif
  precise float value = 0.0;
  precise float amplitude = 1.0;
  for (int octave = 0; octave < terms.whole_octaves; ++octave) {
#ifdef GT_MUTANT_NOISE_FBM_GAIN_BEFORE_SAMPLE
    amplitude = amplitude * terms.gain;  // mutant (both twins): weight updated before its octave
    value = value + FRACTAL_BASIS(q) * amplitude;
#else
    value = value + FRACTAL_BASIS(q) * amplitude;
    amplitude = amplitude * terms.gain;
#endif
    q = q * terms.lacunarity;
  }
  if (terms.remainder != 0.0) value = value + terms.remainder * (FRACTAL_BASIS(q) * amplitude);
  precise float normalised = value * terms.fbm_normalisation;
  return normalised;
}

// (offset − |n(q)|)²
float gt_ridge_signal(vec3 q, float offset) {
  precise float ridge = offset - abs(FRACTAL_BASIS(q));
  precise float squared = ridge * ridge;
  return squared;
}

float gt_ridged_multifractal(vec3 p, GtFractalTerms terms) {
  precise vec3 q = p;
  precise float signal = gt_ridge_signal(q, terms.offset);
  precise float result = signal;
  precise float spectral_weight = terms.spectral_ratio;
  for (int octave = 1; octave < terms.whole_octaves; ++octave) {
    q = q * terms.lacunarity;
#ifdef GT_MUTANT_NOISE_RIDGED_UNCLAMPED_WEIGHT
    precise float weight = signal * terms.gain;  // mutant (both twins): the weight left unclamped
#else
    precise float weight = clamp(signal * terms.gain, 0.0, 1.0);
#endif
    signal = gt_ridge_signal(q, terms.offset) * weight;
    result = result + signal * spectral_weight;
    spectral_weight = spectral_weight * terms.spectral_ratio;
  }
  return result;
}

// ((n(q) + offset)·spectral_weight)·value
float gt_hetero_increment(vec3 q, float offset, float spectral_weight, float value) {
  precise float increment = (FRACTAL_BASIS(q) + offset) * spectral_weight * value;
  return increment;
}

float gt_hetero_terrain(vec3 p, GtFractalTerms terms) {
  precise vec3 q = p;
  precise float value = terms.offset + FRACTAL_BASIS(q);
  q = q * terms.lacunarity;
  precise float spectral_weight = terms.spectral_ratio;
  for (int octave = 1; octave < terms.whole_octaves; ++octave) {
    value = value + gt_hetero_increment(q, terms.offset, spectral_weight, value);
    spectral_weight = spectral_weight * terms.spectral_ratio;
    q = q * terms.lacunarity;
  }
  if (terms.remainder != 0.0) {
    value = value + terms.remainder * gt_hetero_increment(q, terms.offset, spectral_weight, value);
  }
  return value;
}

#endif  // GT_NOISE_FRACTAL_GLSL
