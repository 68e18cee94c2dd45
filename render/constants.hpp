// Every default and tolerance of the render library, written once with its unit and why.
// Not the test thresholds: the golden-image thresholds live beside the golden test.
#pragma once

#include <numbers>

namespace gearsim::render::constants {

// OpenGL version the renderer asks OSMesa for (core profile): 3.3 is the oldest core profile with
// everything used here (GLSL 330, multisample renderbuffers, framebuffer blits).
inline constexpr int kGlMajorVersion = 3;
inline constexpr int kGlMinorVersion = 3;

// Multisample anti-aliasing samples per pixel when multisampling is chosen, normally 4: llvmpipe's
// maximum (GL_MAX_SAMPLES).
inline constexpr int kDefaultMsaaSamples = 4;

// Edge anti-aliasing (edge_antialiasing.hpp): how far, in pixel widths at the edge's distance, the
// surface beside an edge may lie in front of the edge and the edge still count as visible.
// Normally 4: the face next to a concave crease approaches the eye by tan(angle to the view) per
// pixel, so 4 accepts faces up to ~70° from facing the eye at the 1.5 px the farthest pixel a
// column blends lies from the edge; a hidden edge wrongly kept blends two pixels of the surface in
// front, which differ little.
inline constexpr double kEdgeDepthTolerance_px = 4.0;

// Faces whose unit normals' dot product exceeds 1 − this lie in one plane for edge finding: the
// edge between them can never be a silhouette (1e-9: about 0.003° — wall quads split in two differ
// by rounding only).
inline constexpr double kCoplanarCosineTolerance = 1e-9;

// Share of the depth range given to contact markers and force arrows, drawn over the bodies:
// markers take [0, this], bodies (this, 1], so markers always pass the depth test against bodies
// yet one depth buffer holds both (edge anti-aliasing reads it). 1/256 costs the bodies 0.4 % of
// the 24-bit depth resolution.
inline constexpr double kMarkerDepthShare = 1.0 / 256.0;

// Crease angle, rad: adjacent triangles meeting at a smaller angle share a smoothed normal, larger
// angles stay sharp. Normally 30°: a gear's tessellated flanks turn by far less than a degree per
// segment (smooth), while flank/face and flank/bore edges are 90° (crisp).
inline constexpr double kDefaultCreaseAngle_rad = 30.0 * std::numbers::pi / 180.0;

// Chordal deviation of the meshes the planetary helpers tessellate for drawing, m. Normally 5 µm:
// below a pixel in any view of the paper's set (a 5 mm close-up at 720 px has 7 µm pixels), an
// order of magnitude under the 43 µm flank error, and half the triangles of the physics' 0.5 µm.
inline constexpr double kRenderChordalDeviation_m = 5e-6;

// Default vertical field of view of the perspective presets, rad (30°: little distortion).
inline constexpr double kDefaultFieldOfView_rad = 30.0 * std::numbers::pi / 180.0;

// Margin the overview preset leaves around the scene's bounding box, as a fraction of the fitted
// size (5 %): the gearbox fills the frame without touching its edges.
inline constexpr double kOverviewMargin = 0.05;

// Near and far clip planes of the presets, as fractions of the eye–target distance. Depth is 24
// bit: near = 5 % keeps depth steps below 0.1 µm at a close-up's focus point.
inline constexpr double kNearFraction = 0.05;
inline constexpr double kFarFraction = 20.0;

// Largest width or height, px, accepted before asking GL (llvmpipe's renderbuffer limit is 16384).
inline constexpr int kMaxImageSize_px = 16384;

// Rigidity tolerance of a body pose: |RᵀR − I| entries, dimensionless. Poses come from doubles
// composed a few times; 1e-6 accepts their rounding and rejects scales or shears.
inline constexpr double kPoseRigidityTolerance = 1e-6;

// zlib compression level of PNG output: fixed (not libpng's default heuristics) so the bytes are
// reproducible; 6 is zlib's usual speed/size balance.
inline constexpr int kPngCompressionLevel = 6;

// H.264 settings: constant rate factor 20 (visually clean for flat-shaded gears), x264's
// "medium" preset, one encoder thread (x264 output is bit-identical only single-threaded).
inline constexpr int kDefaultVideoCrf = 20;
inline constexpr const char* kDefaultVideoPreset = "medium";
inline constexpr int kVideoEncoderThreads = 1;
inline constexpr const char* kVideoEncoderName = "libx264";

}  // namespace gearsim::render::constants
