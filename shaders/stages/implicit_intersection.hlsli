// The one intersection body of the implicit families: the stage defines
//   ImplicitHit intersectImplicit(ImplicitData object, ObjectRay ray);
// (analytic, or sphere tracing with its SDF) before including this file.
// PT_INSTANCE_ID is the family's first ImplicitData and PT_PRIMITIVE_INDEX
// the object within it.
#ifndef PENUMBRA_IMPLICIT_INTERSECTION_HLSLI
#define PENUMBRA_IMPLICIT_INTERSECTION_HLSLI

PT_HIT_ATTRIBUTES(ImplicitAttributes, gAttributes);

PT_INTERSECTION(main) {
  ImplicitData object = loadImplicit(PT_INSTANCE_ID + PT_PRIMITIVE_INDEX);
  ObjectRay ray = objectRay(object, PT_WORLD_RAY_ORIGIN, PT_WORLD_RAY_DIRECTION, PT_RAY_TMIN, PT_RAY_TCURRENT);
  ImplicitHit hit = intersectImplicit(object, ray);
  if (hit.s >= 0.0) {
    gAttributes.objectNormal = hit.normal;
    PT_REPORT_HIT(hit.s * ray.tPerS, gAttributes);
  }
}

#endif
