// The denoiser's kernels: spatio-temporal variance-guided filtering in the
// manner of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided
// Filtering"), with the edge-avoiding a-trous wavelet filter of Dammertz et
// al. 2010. Everything is filtered as illumination, the radiance minus the
// emission seen at the first non-delta vertex, divided by that vertex's
// albedo; the filtered illumination is multiplied back and the emission added
// (so textures and lights stay sharp).
//
// The entry point defines, before including this file (images of
// denoiser_shared.h, RGBA float, addressed in pixels):
//   DenoiseFrame loadFrame();
//   float4 loadBeauty(int2 p), loadAlbedo(int2 p), loadNormalDepth(int2 p),
//          loadEmission(int2 p), loadSampleMoments(int2 p), loadHistoryIllumination(int2 p),
//          loadHistoryMoments(int2 p), loadHistoryNormalDepth(int2 p), loadIllumination(int2 p),
//          loadMoments(int2 p), loadHistoryAlbedo(int2 p), loadHistoryEmission(int2 p),
//          loadIntegratedAlbedo(int2 p), loadIntegratedEmission(int2 p);
//   void storeIllumination(int2 p, float4 v), storeMoments(...), storeHistoryIllumination(...),
//        storeHistoryNormalDepth(...), storeOutput(...), storeMotion(...),
//        storeIntegratedAlbedo(...), storeIntegratedEmission(...);
// The temporal pass reads this frame's guides (loadAlbedo, loadEmission);
// every later pass the integrated ones.
#ifndef PENUMBRA_DENOISER_HLSLI
#define PENUMBRA_DENOISER_HLSLI
#include "math.hlsli"

bool insideImage(DenoiseFrame f, int2 p) { return p.x >= 0 && p.y >= 0 && p.x < int(f.width) && p.y < int(f.height); }

// The albedo divided out, floored so black surfaces neither divide by zero
// nor lose what they reflect.
float3 demodulationAlbedo(DenoiseFrame f, float3 albedo) { return max(albedo, splat3(f.albedoFloor)); }

// Whether pixel p has illumination to filter: it saw a surface, and one
// that reflects (a black surface, e.g. an emitter's, shows its emission alone,
// and an illumination of 0 there would darken its neighbours).
bool filterableAlbedo(DenoiseFrame f, int2 p, float3 albedo) {
  return loadNormalDepth(p).w > 0.0 && luminance(albedo) > f.albedoFloor;
}
// By this frame's guides (the temporal pass) or the integrated ones (after).
bool filterableNow(DenoiseFrame f, int2 p) { return filterableAlbedo(f, p, loadAlbedo(p).xyz); }
bool filterable(DenoiseFrame f, int2 p) { return filterableAlbedo(f, p, loadIntegratedAlbedo(p).xyz); }

// This frame's illumination at p.
float3 illuminationAt(DenoiseFrame f, int2 p) {
  if (!filterableNow(f, p)) return zero3();
  return (loadBeauty(p).xyz - loadEmission(p).xyz) / demodulationAlbedo(f, loadAlbedo(p).xyz);
}

// Firefly clamp: a pixel brighter than all 8 neighbours is scaled down to
// the brightest of them. It removes isolated spikes (a rare caustic path at
// low spp) at the cost of a small energy loss where a spike is real.
float3 clampFirefly(DenoiseFrame f, int2 p, float3 illumination) {
  float brightest = -1.0;  // no neighbour with illumination: nothing to compare with
  for (int dy = -1; dy <= 1; dy += 1)
    for (int dx = -1; dx <= 1; dx += 1) {
      int2 q = p + int2(dx, dy);
      if ((dx != 0 || dy != 0) && insideImage(f, q) && filterableNow(f, q))
        brightest = max(brightest, luminance(illuminationAt(f, q)));
    }
  if (brightest < 0.0) return illumination;
  float l = luminance(illumination);
  return l > brightest && l > 0.0 ? illumination * (brightest / l) : illumination;
}

// Where the surface seen through pixel p lies (its unfolded, "virtual"
// position for reflections), from the linear view depth.
float3 virtualPosition(DenoiseFrame f, int2 p, float depth) {
  float2 ndc = (float2(p) + float2(0.5, 0.5)) / float2(float(f.width), float(f.height)) * 2.0 - float2(1.0, 1.0);
  float halfHeight = f.camera.filmHalfHeight;
  float3 alongRight = ndc.x * halfHeight * f.camera.aspectRatio * f.camera.right;
  float3 alongUp = ndc.y * halfHeight * f.camera.up;
  if (f.orthographic != 0u) return f.camera.position + (alongRight - alongUp) + f.camera.forward * depth;
  float3 d = f.camera.forward + alongRight - alongUp;
  return f.camera.position + d * depth;  // d's forward component is 1
}

// The previous camera's film position (pixels) of a world point, and its
// linear view depth there (z; <= 0 behind that camera).
float3 projectToPrevious(DenoiseFrame f, float3 world) {
  float3 v = world - f.previousCamera.position;
  float z = dot(v, f.previousCamera.forward);
  // The film's size does not change between frames (Denoiser::record starts a
  // new history when it does); an orthographic film does not shrink with depth.
  float scale = f.orthographic != 0u ? 1.0 : z;
  float halfHeight = f.camera.filmHalfHeight;
  float sx = dot(v, f.previousCamera.right) / (scale * halfHeight * f.camera.aspectRatio);
  float sy = dot(v, f.previousCamera.up) / (scale * halfHeight);
  return float3((sx + 1.0) * 0.5 * float(f.width), (1.0 - sy) * 0.5 * float(f.height), z);
}

// The length the depth tolerances are relative to at `depth`: the depth for a
// perspective camera (a pixel's footprint grows with it), the view's height
// for an orthographic one (its footprint is the same at any depth, and depth
// counts from wherever the film plane was put): as much as a perspective
// camera of 53 degrees (a film as tall as its distance) sees at that depth.
float depthScale(DenoiseFrame f, float depth) {
  return f.orthographic != 0u ? 2.0 * f.camera.filmHalfHeight : depth;
}

float3 unitOrZero(float3 v) {
  float l = length(v);
  return l > 0.0 ? v / l : zero3();
}

// Pass DN_PASS_TEMPORAL.
void denoiseTemporal(int2 p, uint flags) {
  DenoiseFrame f = loadFrame();
  float4 nd = loadNormalDepth(p);
  float depth = nd.w;
  float3 albedo = demodulationAlbedo(f, loadAlbedo(p).xyz);
  float3 illumination = illuminationAt(f, p);
  if ((flags & DN_FLAG_FIREFLY_CLAMP) != 0u && filterableNow(f, p)) illumination = clampFirefly(f, p, illumination);
  // Luminance moments of the samples' illumination (demodulated by the
  // albedo's luminance: the guide holds those of radiance - emission).
  float inverseAlbedo = 1.0 / luminance(albedo);
  float2 sampleMoments = loadSampleMoments(p).xy * float2(inverseAlbedo, inverseAlbedo * inverseAlbedo);
  float samples = float(f.samplesPerPixel);

  float3 integrated = illumination;
  float3 currentAlbedo = loadAlbedo(p).xyz;
  float3 currentEmission = loadEmission(p).xyz;
  float3 integratedAlbedo = currentAlbedo;
  float3 integratedEmission = currentEmission;
  float2 moments = sampleMoments;
  float historyLength = 1.0;
  float2 motion = float2(0.0, 0.0);
  if ((flags & DN_FLAG_TEMPORAL) != 0u && depth > 0.0) {
    float3 world = virtualPosition(f, p, depth);
    float3 previous = projectToPrevious(f, world);
    motion = previous.xy - (float2(p) + float2(0.5, 0.5));
    if ((flags & DN_FLAG_HISTORY_VALID) != 0u && previous.z > 0.0) {
      // Bilinear taps of the history, each kept only where the surface it
      // saw is this one (depth within 10 % of depthScale, normals within ~25 degrees, the
      // same kind of material): anything else is a disocclusion and
      // restarts the history.
      float2 tapOrigin = previous.xy - float2(0.5, 0.5);
      int2 base = int2(floor(tapOrigin));
      float2 t = tapOrigin - float2(base);
      float3 normal = unitOrZero(nd.xyz);
      float3 sumIllumination = zero3();
      float3 sumAlbedo = zero3();
      float3 sumEmission = zero3();
      float3 sumMoments = zero3();
      float sumWeight = 0.0;
      int2 spot = int2(floor(previous.xy));
      bool still = dot(motion, motion) < 1e-4;
      float spotAlbedo = insideImage(f, spot) ? luminance(loadHistoryAlbedo(spot).xyz) : 0.0;
      float spotEmission = insideImage(f, spot) ? luminance(loadHistoryEmission(spot).xyz) : 0.0;
      // The four bilinear taps; where none is this surface (1 spp guides
      // flip between the two sides of an edge from frame to frame), the 3x3
      // history pixels around the spot that are, with equal weights, as
      // SVGF does.
      for (int pass = 0; pass < 2 && sumWeight <= 1e-4; pass += 1) {
        int taps = pass == 0 ? 4 : 9;
        for (int k = 0; k < taps; k += 1) {
          int2 offset = pass == 0 ? int2(k & 1, k >> 1) : int2(k % 3 - 1, k / 3 - 1);
          int2 q = (pass == 0 ? base : spot) + offset;
          if (!insideImage(f, q)) continue;
          float4 hnd = loadHistoryNormalDepth(q);
          if (!(hnd.w > 0.0) || abs(hnd.w - previous.z) > 0.1 * depthScale(f, previous.z)) continue;
          if (dot(normal, unitOrZero(hnd.xyz)) < 0.9) continue;
          // A light 0.1 mm below a ceiling passes both tests: the albedo
          // and the emission must match as well (luminance within a factor
          // of 2), or the light's emission would smear onto the ceiling. The
          // albedo alone lets a pixel half light, half ceiling (half the
          // ceiling's albedo) through to the ceiling beside it as the camera
          // moves; its emission does not. Compared with this frame's guides,
          // except for a camera that has not moved (by 0.01 pixel): its
          // bilinear taps are compared with the history at the spot itself,
          // so an edge pixel keeps its own history whichever side its 1 spp
          // sample hit this frame. Only a still camera: history compared with
          // history confirms itself, so a camera panning by less than half a
          // pixel a frame (the bound this once had) dragged the light's
          // emission along behind its edge.
          float4 historyAlbedo = loadHistoryAlbedo(q);
          float4 historyEmission = loadHistoryEmission(q);
          bool atSpot = still && pass == 0;
          float la = luminance(historyAlbedo.xyz), lb = atSpot ? spotAlbedo : luminance(currentAlbedo);
          if (abs(la - lb) > 0.5 * max(la, lb)) continue;
          float le = luminance(historyEmission.xyz), lf = atSpot ? spotEmission : luminance(currentEmission);
          if (abs(le - lf) > 0.5 * max(le, lf)) continue;
          float w = pass == 0 ? (offset.x == 1 ? t.x : 1.0 - t.x) * (offset.y == 1 ? t.y : 1.0 - t.y) : 1.0;
          sumIllumination += w * loadHistoryIllumination(q).xyz;
          sumAlbedo += w * historyAlbedo.xyz;
          sumEmission += w * historyEmission.xyz;
          sumMoments += w * loadHistoryMoments(q).xyz;
          sumWeight += w;
        }
      }
      if (sumWeight > 1e-4) {
        float3 historyMoments = sumMoments / sumWeight;
        historyLength = min(historyMoments.z + 1.0, float(f.maxHistory));
        // A running mean until the history is full, then an exponential one.
        float alpha = 1.0 / historyLength;
        integrated = lerp(sumIllumination / sumWeight, illumination, alpha);
        integratedAlbedo = lerp(sumAlbedo / sumWeight, integratedAlbedo, alpha);
        integratedEmission = lerp(sumEmission / sumWeight, integratedEmission, alpha);
        moments = lerp(historyMoments.xy, sampleMoments, alpha);
      }
    }
  }
  // The variance of the mean of the samples behind the pixel.
  float behind = samples * historyLength;
  float variance = max(0.0, moments.y - moments.x * moments.x) / behind;
  storeIllumination(p, float4(integrated, variance));
  storeMoments(p, float4(moments, historyLength, behind));
  storeHistoryNormalDepth(p, nd);
  storeMotion(p, float4(motion, 0.0, 0.0));
  storeIntegratedAlbedo(p, float4(integratedAlbedo, 0.0));
  storeIntegratedEmission(p, float4(integratedEmission, 0.0));
}

// Edge-stopping weights of pixel q for the centre p (depth with the centre's
// screen-space depth gradient, normal, and luminance normalised by the
// centre's standard deviation), as SVGF's. A sigma or exponent of 0 turns
// that test off (for measuring what each one does).
float edgeWeight(DenoiseFrame f, float depthP, float2 gradient, float3 normalP, float luminanceP,
                 float sigmaLuminance, float4 ndQ, float luminanceQ, float2 offset) {
  float w = 1.0;
  if (f.depthSigma > 0.0)
    w *= exp(-abs(ndQ.w - depthP) / (f.depthSigma * abs(dot(gradient, offset)) + 1e-3 * depthScale(f, depthP) + 1e-8));
  // A pixel whose samples' normals cancel (both sides of a thin surface) has
  // no normal to compare.
  float3 normalQ = unitOrZero(ndQ.xyz);
  if (f.normalExponent > 0.0 && dot(normalP, normalP) > 0.0 && dot(normalQ, normalQ) > 0.0)
    w *= pow(max(0.0, dot(normalP, normalQ)), f.normalExponent);
  if (f.luminanceSigma > 0.0) w *= exp(-abs(luminanceP - luminanceQ) / sigmaLuminance);
  return w;
}

// The smaller one-sided depth difference in x and y: a slope across the
// pixel, not across a neighbouring edge.
float2 depthGradient(DenoiseFrame f, int2 p, float depth) {
  float2 g;
  float l = insideImage(f, p - int2(1, 0)) ? loadNormalDepth(p - int2(1, 0)).w : depth;
  float r = insideImage(f, p + int2(1, 0)) ? loadNormalDepth(p + int2(1, 0)).w : depth;
  float u = insideImage(f, p - int2(0, 1)) ? loadNormalDepth(p - int2(0, 1)).w : depth;
  float d = insideImage(f, p + int2(0, 1)) ? loadNormalDepth(p + int2(0, 1)).w : depth;
  g.x = min(abs(r - depth), abs(depth - l));
  g.y = min(abs(d - depth), abs(depth - u));
  return g;
}

// Pass DN_PASS_VARIANCE: where fewer than 4 samples lie behind a pixel
// (history just reset, or a 1-3 spp single frame), its variance is
// estimated from the 7x7 neighbourhood (weighted by depth and normal), and
// boosted while the history is short, as SVGF does.
void denoiseVariance(int2 p) {
  DenoiseFrame f = loadFrame();
  float4 centre = loadIllumination(p);
  float4 nd = loadNormalDepth(p);
  float4 m = loadMoments(p);
  if (m.w >= 4.0 || !filterable(f, p)) {
    storeIllumination(p, centre);
    return;
  }
  float3 normal = unitOrZero(nd.xyz);
  float2 gradient = depthGradient(f, p, nd.w);
  float sumWeight = 0.0;
  float2 sum = float2(0.0, 0.0);
  for (int dy = -3; dy <= 3; dy += 1)
    for (int dx = -3; dx <= 3; dx += 1) {
      int2 q = p + int2(dx, dy);
      if (!insideImage(f, q) || !filterable(f, q)) continue;
      float4 ndQ = loadNormalDepth(q);
      float l = luminance(loadIllumination(q).xyz);
      // Luminance does not stop this estimate: it is what is being measured.
      float w = edgeWeight(f, nd.w, gradient, normal, 0.0, 1e30, ndQ, 0.0, float2(dx, dy));
      sum += w * float2(l, l * l);
      sumWeight += w;
    }
  float2 moments = sum / max(sumWeight, 1e-8);
  float variance = max(0.0, moments.y - moments.x * moments.x) * (4.0 / max(m.w, 1.0));
  storeIllumination(p, float4(centre.xyz, variance));
}

// The luminance test's scale for a pixel of this variance: sigma_l standard
// deviations.
float luminanceScale(DenoiseFrame f, float variance) { return f.luminanceSigma * sqrt(max(variance, 0.0)) + 1e-10; }

// Pass DN_PASS_ATROUS: one iteration of the 5x5 B3-spline kernel with holes
// of stepWidth pixels; the variance is filtered with the squared weights.
void denoiseAtrous(int2 p, uint stepWidth, uint flags) {
  DenoiseFrame f = loadFrame();
  float4 centre = loadIllumination(p);
  float4 nd = loadNormalDepth(p);
  if (!filterable(f, p)) {
    storeIllumination(p, centre);
    if ((flags & DN_FLAG_WRITE_HISTORY) != 0u) storeHistoryIllumination(p, centre);
    return;
  }
  // The luminance scale: the standard deviation, from a 3x3 Gaussian of the variance.
  float blurredVariance = 0.0;
  float blurWeight = 0.0;
  for (int dy = -1; dy <= 1; dy += 1)
    for (int dx = -1; dx <= 1; dx += 1) {
      int2 q = p + int2(dx, dy);
      if (!insideImage(f, q)) continue;
      float w = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
      blurredVariance += w * loadIllumination(q).w;
      blurWeight += w;
    }
  float sigmaLuminance = luminanceScale(f, blurredVariance / blurWeight);
  float3 normal = unitOrZero(nd.xyz);
  float2 gradient = depthGradient(f, p, nd.w);
  float luminanceP = luminance(centre.xyz);
  float kernel[3] = {3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0};
  float3 sum = zero3();
  float sumVariance = 0.0;
  float sumWeight = 0.0;
  for (int dy = -2; dy <= 2; dy += 1)
    for (int dx = -2; dx <= 2; dx += 1) {
      int2 offset = int2(dx, dy) * int(stepWidth);
      int2 q = p + offset;
      if (!insideImage(f, q) || !filterable(f, q)) continue;
      float4 ndQ = loadNormalDepth(q);
      float4 v = loadIllumination(q);
      // The luminance scale of the pair, the larger of the two pixels':
      // with the centre's alone, a bright sample's high-variance pixel
      // averaged it away while its low-variance neighbours excluded it, and
      // its light was lost (3-4 % of a 1-4 spp Cornell box's).
      float sigmaPair = max(sigmaLuminance, luminanceScale(f, v.w));
      float w = kernel[abs(dx)] * kernel[abs(dy)] *
                edgeWeight(f, nd.w, gradient, normal, luminanceP, sigmaPair, ndQ, luminance(v.xyz),
                           float2(offset));
      sum += w * v.xyz;
      sumVariance += w * w * v.w;
      sumWeight += w;
    }
  // The centre's own weight is kernel[0]^2 > 0; should it underflow, the
  // pixel stays as it is.
  float4 filtered = sumWeight > 0.0 ? float4(sum / sumWeight, sumVariance / (sumWeight * sumWeight)) : centre;
  storeIllumination(p, filtered);
  if ((flags & DN_FLAG_WRITE_HISTORY) != 0u) storeHistoryIllumination(p, filtered);
}

// Pass DN_PASS_COMPOSE: radiance = illumination x albedo + emission (both
// integrated); pixels that saw no surface keep the path tracer's radiance,
// black ones (an emitter) show their emission.
void denoiseCompose(int2 p, uint flags) {
  DenoiseFrame f = loadFrame();
  float4 beauty = loadBeauty(p);
  if (loadNormalDepth(p).w <= 0.0) {
    storeOutput(p, float4(beauty.xyz, 1.0));
    return;
  }
  float3 emission = loadIntegratedEmission(p).xyz;
  if (!filterable(f, p)) {
    // A single frame keeps its radiance whole; a temporal one its emission's mean.
    storeOutput(p, float4((flags & DN_FLAG_TEMPORAL) != 0u ? emission : beauty.xyz, 1.0));
    return;
  }
  float3 albedo = demodulationAlbedo(f, loadIntegratedAlbedo(p).xyz);
  float3 radiance = loadIllumination(p).xyz * albedo + emission;
  storeOutput(p, float4(radiance, 1.0));
}

void denoisePass(int2 p, DenoisePush push) {
  if (!insideImage(loadFrame(), p)) return;
  if (push.pass == DN_PASS_TEMPORAL) denoiseTemporal(p, push.flags);
  else if (push.pass == DN_PASS_VARIANCE) denoiseVariance(p);
  else if (push.pass == DN_PASS_ATROUS) denoiseAtrous(p, push.stepWidth, push.flags);
  else denoiseCompose(p, push.flags);
}

#endif
