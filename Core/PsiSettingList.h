// PsiSettingList: every scalar setting of 'Psi Volume', one line each, declared here once. From
// this list follow the psi::Settings and psi::InteractionSettings members with their defaults,
// the psi::Setting enumerators, the rows of psi::SettingTable() (name, kind, range;
// PsiSettings.cxx), vtkPsiVolumeMapper's Set/Get and vtkPsiVolumeRepresentation's setters. Adding a
// setting is its line here plus its property in XML/PsiVolumeRepresentation.xml (PsiCore.Settings
// checks that the two agree: default, enumeration entries, range); docs/architecture.md "Adding a
// setting".
//
// ENUM(Name, Type, Default, Last): a typed enumeration psi::Type (PsiSettings.h) whose values
//   0..Last are the XML's <Entry> numbers; C++ holds the enumerator, the setters take the number.
// NUMBER(Name, Type, Default, Min, Max, Where): an int or double in [Min, Max].
// BOOL(Name, Default, Where).
// Where: PROPERTY, a property of the representation (XML), or MAPPER, set on the mapper only
// (a research or testing switch with no panel entry).
//
// The lists are plain macros, which VTK's wrappers expand too: the setters generated from them
// are wrapped for ParaView's XML and for Python.
#ifndef PsiSettingList_h
#define PsiSettingList_h

// What the mapper draws with (psi::Settings):
//  IntegrationMethod: ray integration in each cell, a row of psi::IntegrationMethodTable()
//    (PsiIntegrationMethods.h documents each); default partial pre-integration.
//  SortMethod: visibility order (psi::Sorts).
//  Projector: the stage that projects the tetrahedra (psi::Projectors; both run the same
//    classification and emission, Shaders/PsiVolumeGS.glsl). The compute shader asked for where
//    OpenGL 4.3 is missing draws with the geometry shader, with a warning.
//  Decomposition: how each projection is drawn (psi::Decompositions).
//  ExactPerspectiveSegments: with the fan in perspective, exact segments from the face planes.
//  EarlyDiscard: drop tetrahedra whose scalar range sees zero opacity only, in the geometry
//    shader (Maximo et al. 2010 §3.5; used only where the opacity function has zero regions).
//  EarlyRayTermination: composite front to back and stop shading a pixel once it is opaque
//    (psi::EarlyRayTerminations; never within depth peeling). Its 0 and 1 are the former
//    switch's off and on, so that a state file saved with the switch keeps its meaning.
//  TransferFunctionSamples: samples of the transfer-function table.
//  AdaptiveSampling: split segments at transfer-function nodes (Moreland's dissertation §4.3).
//  IsosurfaceOpacity: opacity of every isovalue without its own (0..1; 1 hides what is behind).
//  IsosurfaceUseColorMap: color each isosurface through the color map at its value (else
//    IsosurfaceColor).
//  IsosurfaceMethod: marching tetrahedra in the geometry shader or per fragment
//    (psi::IsosurfaceMethods; Maximo et al. 2010 §3.4); past the driver's geometry-output limit
//    marching tetrahedra fall back to per fragment.
//  IsosurfaceShading: psi::IsosurfaceShadings.
//  RasterFloor: benchmarks only (Benchmarks/bench_ways.py): every fragment writes one constant
//    color, the cost of the same triangles without shading (psi::ShaderFeatures::RasterFloor).
#define PSI_RENDER_SETTINGS(ENUM, NUMBER, BOOL)                                                    \
  ENUM(IntegrationMethod, Method, PartialPreIntegration, FullPreIntegration)                       \
  ENUM(SortMethod, Sorts, MPVONC, MPVONC)                                                          \
  ENUM(Projector, Projectors, Auto, Auto)                                                          \
  ENUM(Decomposition, Decompositions, Auto, Auto)                                                  \
  BOOL(ExactPerspectiveSegments, true, MAPPER)                                                     \
  BOOL(EarlyDiscard, true, PROPERTY)                                                               \
  ENUM(EarlyRayTermination, EarlyRayTerminations, Auto, On)                                        \
  NUMBER(TransferFunctionSamples, int, 1024, 2, 65536, MAPPER)                                     \
  ENUM(AdaptiveSampling, AdaptiveModes, Auto, Auto)                                                \
  NUMBER(IsosurfaceOpacity, double, 1, 0, 1, PROPERTY)                                             \
  BOOL(IsosurfaceUseColorMap, true, PROPERTY)                                                      \
  ENUM(IsosurfaceMethod, IsosurfaceMethods, Auto, Auto)                                            \
  ENUM(IsosurfaceShading, IsosurfaceShadings, Smooth, Unlit)                                       \
  BOOL(RasterFloor, false, MAPPER)

// What the representation draws while the camera moves (psi::InteractionSettings; the mapper
// never sees them):
//  InteractionMode: psi::InteractionModes.
//  InteractiveBudget: seconds an interactive frame may take; 'Auto' draws the level of detail
//    while the camera moves when the last still frame took longer (0.1 s keeps an interaction
//    near 10 frames a second).
#define PSI_INTERACTION_SETTINGS(ENUM, NUMBER, BOOL)                                               \
  ENUM(InteractionMode, InteractionModes, Auto, FullFrame)                                         \
  NUMBER(InteractiveBudget, double, 0.1, 0, 60, PROPERTY)

#endif
