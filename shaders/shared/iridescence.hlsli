// Thin-film interference (KHR_materials_iridescence): a film of index
// filmIor and thickness d (nm) on the specular layer turns its Fresnel
// reflectance into the Airy sum of the waves reflected at the film's two
// interfaces. Belcour and Barla 2017 ("A Practical Extension to Microfacet
// Theory for the Modeling of Varying Iridescence") integrate that sum
// against the CIE curves in closed form: the incoherent part C0 stays grey,
// and the first two interference terms are cosines in optical path
// difference whose colour is the curves' Gaussian fit in Fourier space.
// The glTF extension defines its reflectance this way, with Schlick's
// approximation at both interfaces and air outside.
#ifndef PENUMBRA_IRIDESCENCE_HLSLI
#define PENUMBRA_IRIDESCENCE_HLSLI
#include "fresnel.hlsli"
#include "math.hlsli"
#include "spectrum.hlsli"

// F0 of a boundary from index `incident` into index `transmitted`.
float3 fresnelF0(float3 transmitted, float incident) {
  float3 r = (transmitted - splat3(incident)) / (transmitted + splat3(incident));
  return r * r;
}

// The index (from air) that has reflectance f0 at normal incidence.
float3 iorFromF0(float3 f0) {
  float3 s = sqrt(f0);
  return (splat3(1.0) + s) / (splat3(1.0) - s);
}

// The CIE 1931 curves' response (XYZ, relative to white: equal energy) to
// a cosine of optical path difference `opd` nm in phase: Belcour and
// Barla's Gaussian fit, evaluated in Fourier space.
float3 thinFilmXyz(float opd) {
  float phase = 2.0 * kPi * opd * 1.0e-9;
  float3 val = float3(5.4856e-13, 4.4201e-13, 5.2481e-13);
  float3 pos = float3(1.6810e+06, 1.7953e+06, 2.2084e+06);
  float3 var = float3(4.3278e+09, 9.3046e+09, 6.6121e+09);
  float3 xyz = val * sqrt(2.0 * kPi * var) * cos(pos * phase) * exp(-(phase * phase) * var);
  xyz.x += 9.7470e-14 * sqrt(2.0 * kPi * 4.5282e+09) * cos(2.2399e+06 * phase) *
           exp(-4.5282e+09 * phase * phase);
  return xyz / 1.0685e-7;
}

// What a film shows at one cosine whatever lies below it: the metal and
// dielectric layers share it.
struct ThinFilm {
  float eta2;       // the film's index (faded to air's for the thinnest films)
  float cosTheta2;  // inside the film
  float r12;        // air to film
  float3 xyz1;      // the first and second interference orders' responses,
  float3 xyz2;      // before their phase shifts
};

ThinFilm thinFilmAt(float filmIor, float thicknessNm, float cosTheta) {
  ThinFilm f;
  // A vanishing film is no film: its index fades to air's below 30 nm.
  f.eta2 = lerp(1.0, filmIor, smoothstep(0.0, 30.0, thicknessNm));
  float sin2Theta2 = (1.0 - cosTheta * cosTheta) / (f.eta2 * f.eta2);
  f.cosTheta2 = sqrt(max(0.0, 1.0 - sin2Theta2));
  // Air to film: the film's index is >= 1, so no total internal reflection.
  f.r12 = fresnelSchlick(fresnelF0(splat3(f.eta2), 1.0), cosTheta).x;
  float opd = 2.0 * f.eta2 * thicknessNm * f.cosTheta2;
  f.xyz1 = thinFilmXyz(opd);
  f.xyz2 = thinFilmXyz(2.0 * opd);
  return f;
}

// The film's reflectance over a base of reflectance baseF0, per channel, in
// [0, 1]: the incoherent sum (order 0), then the first two interference
// orders. The phases are multiples of pi: the film's index is >= air's, so
// the way back out of the film turns the phase by pi (phi21), and the base
// by pi where its index is below the film's; order m's shift m phi only
// flips the sign of its cosine. As the extension's reference code has it,
// channel k's shift applies to the k-th XYZ component.
float3 thinFilmReflectance(ThinFilm f, float3 baseF0) {
  float t121 = 1.0 - f.r12;
  // The base's index from its F0 (kept below 1, so the index stays finite).
  float3 baseIor = iorFromF0(clamp(baseF0, splat3(0.0), splat3(0.9999)));
  float3 r23 = fresnelSchlick(fresnelF0(baseIor, f.eta2), f.cosTheta2);
  // cos(phi21 + phi23) for order 1 (-1 without the base's turn, +1 with it); order 2: +1.
  float3 sign1 = float3(baseIor.x < f.eta2 ? 1.0 : -1.0, baseIor.y < f.eta2 ? 1.0 : -1.0,
                        baseIor.z < f.eta2 ? 1.0 : -1.0);
  float3 r123 = clamp(f.r12 * r23, splat3(1e-5), splat3(0.9999));
  float3 amplitude = sqrt(r123);
  float3 rs = t121 * t121 * r23 / (splat3(1.0) - r123);
  float3 c1 = (rs - t121) * amplitude;
  float3 c2 = c1 * amplitude;
  float3 result =
      f.r12 + rs + c1 * 2.0 * xyzToRec709(sign1 * f.xyz1) + c2 * 2.0 * xyzToRec709(f.xyz2);
  return saturate(result);
}

#endif
