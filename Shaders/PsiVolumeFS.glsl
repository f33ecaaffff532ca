//VTK::System::Dec
#extension GL_ARB_shader_bit_encoding : enable
//PSI::Counts::Dec
//VTK::Output::Dec
// PsiVolumeFS: integrates the ray segment through one tetrahedron (front scalar, back scalar,
// thickness interpolated from the geometry shader) and outputs premultiplied color, blended
// back to front with (ONE, ONE_MINUS_SRC_ALPHA) into a floating-point target.
//
// This is the template of the fragment shader. psi::ComposeShaders (PsiShaderComposer.cxx)
// replaces each `//PSI::<Feature>::<Site>` tag with the section of that name in the feature's
// file (PsiExactSegmentsFS.glsl, PsiNearClipFS.glsl, PsiIsoTrianglesFS.glsl, ...), or with
// nothing when the scene does not call for the feature; //PSI::Integrator::Impl receives the
// integration method (Shaders/PsiIntegrate*.glsl), which defines
// vec4 integrateSegment(float sf, float sb, float D).

uniform mat4 DCVCMatrix;            // inverse projection: window depth -> view distance
uniform mat4 VCDCMatrix;            // projection
uniform vec2 viewportSize;
uniform int parallelProjection;

// vec4 transfer(float s): luminance and attenuation at scalar s, from the sampled table
// (PsiTransferTableFS.glsl) or, with adaptive sampling, from the nodes (PsiTransferNodesFS.glsl).
//PSI::SeparateOpacity::Dec
//PSI::Transfer::Impl

// The view-space point of this pixel at window depth `depth`.
vec3 viewPointAt(float depth)
{
  vec4 ndc = vec4(2.0 * gl_FragCoord.xy / viewportSize - 1.0, 2.0 * depth - 1.0, 1.0);
  vec4 p = DCVCMatrix * ndc;
  return p.xyz / p.w;
}

//PSI::Integrator::PsiTable
//PSI::Integrator::UnitDistance
//PSI::Integrator::PreIntegrated
//PSI::Integrator::Impl

//PSI::HAPTSegments::Dec
//PSI::ExactSegments::Dec
//PSI::RaySegments::Dec
//PSI::NearClip::Dec
//PSI::SceneDepth::Dec
//PSI::IsoShade::Dec
//PSI::IsoTriangles::Dec
//PSI::IsoPerFragment::Dec
//PSI::SegmentSplit::Dec
//PSI::DepthPeel::Dec

// Writes the segment's premultiplied color.
void writeColor(vec4 c)
{
  if (!(c.a > 0.0))
  {
    discard; // fully transparent, or a NaN that must not reach the image
  }
  gl_FragData[0] = c;
}

void main()
{
//PSI::IsoTriangles::Surface
//PSI::DepthPeel::Early
  float sf, sb, D;
  readSegment(sf, sb, D);
  float frontDepth = segmentFrontDepth();
  vec3 pFront = vec3(0.0), rayDir = vec3(0.0, 0.0, -1.0);
//PSI::IsoPerFragment::Impl
//PSI::NearClip::Impl
  // Fragments behind opaque geometry are rejected by the depth test against the scene's depth.
//PSI::SceneDepth::Impl
//PSI::OpaqueClip::Impl
//PSI::DepthPeel::Impl
//PSI::IsoTriangles::Impl
//PSI::SegmentSplit::Integrate
  writeColor(integrateSegment(sf, sb, max(D, 0.0)));
}
