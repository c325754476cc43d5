#include "cardiac/patient/patient_wall.h"

#include "cardiac/anatomy/aha_segments.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cardiac/patient/patient_wall_internal.h"
#include "mesh/surface_remesh.h"
#include "mesh/wall_extrusion.h"

namespace hs::cardiac {

namespace {

// A heart's largest extent, base to apex or across: 3-30 cm (a neonate's to a dilated adult
// ventricle, with room for a whole-heart segmentation).
constexpr double kSmallestHeart = 0.03, kLargestHeart = 0.30;
// The base plate is thinner than the wall, as in the procedural heart (0.3 of 0.5).
constexpr double kBaseThicknessShare = 0.6;
// From the mitral-to-aortic direction to the septum's: the aortic root lies at the
// anteroseptal position, between AHA segments 1 and 2 (Cerqueira et al. 2002). On biv-me's
// patient 1 the septum so found lies 11 degrees from the one its biventricular epicardium
// gives (56 without the turn; tests/io/mesh/test_patient_meshes.cpp).
constexpr double kAorticToSeptumRad = 45.0 * 3.14159265358979323846 / 180.0;

std::string format(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw std::invalid_argument(file + ": " + what);
}

Surface inMetres(const Surface& s, double metresPerUnit) {
  Surface out = s;
  for (Vec3& p : out.vertices) p = (p.cast<double>() * metresPerUnit).cast<pbd::Real>();
  return out;
}

double largestExtent(const std::vector<Vec3>& v) {
  if (v.empty()) return 0;
  Vec3d lo = v[0].cast<double>(), hi = lo;
  for (const Vec3& p : v) lo = lo.cwiseMin(p.cast<double>()), hi = hi.cwiseMax(p.cast<double>());
  return (hi - lo).maxCoeff();
}

Vec3d principalAxis(const std::vector<Vec3>& vertices) {
  Vec3d mean = Vec3d::Zero();
  for (const Vec3& p : vertices) mean += p.cast<double>() / double(vertices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : vertices) cov += (p.cast<double>() - mean) * (p.cast<double>() - mean).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(2);
}

// The annuli's loop numbers (0-based) by size or as overridden.
std::pair<std::size_t, std::size_t> chooseAnnuli(const std::vector<detail::LoopShape>& shapes,
                                                 const PatientWallSettings& s) {
  const auto checkNumber = [&](int number, const char* key) {
    if (number < 0 || number > static_cast<int>(shapes.size()))
      fail(s.file, std::string(key) + " " + std::to_string(number) + ": expected a loop number in [1, " +
                       std::to_string(shapes.size()) + "]");
  };
  checkNumber(s.mitralLoop, s.mitralLoopName.c_str());
  checkNumber(s.aorticLoop, s.aorticLoopName.c_str());
  const std::size_t larger = shapes[0].vectorArea.norm() >= shapes[1].vectorArea.norm() ? 0 : 1;
  std::size_t mitral = larger, aortic = 1 - larger;
  if (s.mitralLoop > 0) mitral = static_cast<std::size_t>(s.mitralLoop - 1), aortic = 1 - mitral;
  if (s.aorticLoop > 0)
    aortic = static_cast<std::size_t>(s.aorticLoop - 1), mitral = s.mitralLoop > 0 ? mitral : 1 - aortic;
  if (mitral == aortic)
    fail(s.file, s.mitralLoopName + " and " + s.aorticLoopName + " are both loop " + std::to_string(mitral + 1) +
                     "; expected two different loops");
  return {mitral, aortic};
}

// The long axis, unit, from the apex (the point farthest from the base along the principal
// axis of the vertices) to the base centre.
Vec3d longAxis(const Surface& s, const Vec3d& baseCentre) {
  Vec3d mean = Vec3d::Zero();
  for (const Vec3& p : s.vertices) mean += p.cast<double>() / double(s.vertices.size());
  Vec3d principal = principalAxis(s.vertices);
  if ((baseCentre - mean).dot(principal) < 0) principal = -principal;
  Vec3d apex = s.vertices[0].cast<double>();
  for (const Vec3& p : s.vertices)
    if ((p.cast<double>() - baseCentre).dot(principal) < (apex - baseCentre).dot(principal))
      apex = p.cast<double>();
  return (baseCentre - apex).normalized();
}

HeartFrame frameOf(const Vec3d& y, const Vec3d& baseCentre, const Vec3d& septumHint, double metresPerUnit,
                   const std::string& file, const std::string& septumName) {
  const Vec3d septum = septumHint - y * y.dot(septumHint);
  if (septumHint.norm() == 0 || septum.norm() < 1e-6 * septumHint.norm())
    fail(file, septumName + " lies along the long axis; expected one across it");
  // The file's septal and anterior directions across the long axis become the heart frame's
  // kSeptal and kAnterior (aha_segments.h): row k of the rotation is the file direction of the
  // frame's axis k, kAnterior_k anterior + kSeptal_k septal (the septum, the long axis and the
  // anterior make a right-handed heart, as kAnterior, kSeptal and y do).
  const Vec3d septal = septum.normalized();
  const Vec3d anterior = y.cross(septal);
  HeartFrame f;
  f.rotation.row(0) = (kAnterior.x() * anterior + kSeptal.x() * septal).transpose();
  f.rotation.row(1) = y.transpose();
  f.rotation.row(2) = (kAnterior.z() * anterior + kSeptal.z() * septal).transpose();
  f.origin = baseCentre;
  f.metresPerUnit = metresPerUnit;
  return f;
}

// The remeshed endocardium's chords cut inside the curved input, so its cavity is short of the
// input's (biv-me: 0.8% at 5 mm edges, 2.1% at 8 mm) and a recorded beat's volumes would be
// missed by that much. The wall's inner surface (layer 0 of the extrusion, the surface's own
// vertices) moves out together until it holds the input's volume (pbd::restoreCappedVolume,
// a tenth of a millimetre at 5 mm). After the extrusion, so that the mesher's discrete choices
// are made on the remeshed surface itself: the move only thins the first layer a little.
void restoreCavityVolume(Surface& surface, pbd::TetMesh& mesh, double inputVolume) {
  pbd::restoreCappedVolume(surface.vertices, surface.triangles, inputVolume);
  std::copy(surface.vertices.begin(), surface.vertices.end(), mesh.vertices.begin());
}

Vec3d areaCentroid(const Surface& s) {
  Vec3d sum = Vec3d::Zero();
  double area = 0;
  for (const pbd::Triangle& t : s.triangles) {
    const Vec3d a = s.vertices[t[0]].cast<double>(), b = s.vertices[t[1]].cast<double>(),
                c = s.vertices[t[2]].cast<double>();
    const double w = 0.5 * (b - a).cross(c - a).norm();
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  return area > 0 ? Vec3d(sum / area) : sum;
}

// An epicardium around both ventricles (biv-me's) is centred well off the left ventricle's
// long axis, toward the right ventricle: the septum's side. Its offset across the axis, or
// zero for an epicardium of the left ventricle alone (offset below 0.3 of the cavity's mean
// radius).
Vec3d rightVentricleSide(const Surface& endo, const Surface& epi, const Vec3d& y) {
  const Vec3d c = areaCentroid(endo);
  double radius = 0;
  for (const Vec3& p : endo.vertices) {
    const Vec3d d = p.cast<double>() - c;
    radius += (d - y * y.dot(d)).norm() / double(endo.vertices.size());
  }
  const Vec3d offset = areaCentroid(epi) - c;
  const Vec3d across = offset - y * y.dot(offset);
  return across.norm() > 0.3 * radius ? across : Vec3d::Zero();
}

// A manifold, consistently oriented surface in one piece, whose loops close (a loop that does
// not close is where the orientation flips).
void checkTopology(const Surface& s, const std::string& file) {
  for (const pbd::Triangle& t : s.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      fail(file, "a triangle uses one vertex twice; expected three distinct corners");
  const pbd::SurfaceCheck check = pbd::checkSurface(s.triangles);
  if (check.nonManifoldEdges > 0)
    fail(file, std::to_string(check.nonManifoldEdges) +
                   " edges are shared by more than two triangles; expected a manifold surface");
  if (!check.consistentlyOriented)
    fail(file,
         "neighbouring triangles are wound in opposite directions; expected a consistently oriented surface");
  if (const std::size_t pieces = pbd::connectedPieces(s.vertices.size(), s.triangles); pieces != 1)
    fail(file, std::to_string(pieces) + " separate pieces; expected one connected endocardium");
}

// A closed surface keeps a truncated ventricle's base as its largest flat face: cut it off.
Surface withoutFlatBase(const Surface& s, const std::string& file) {
  double flatArea = 0, totalArea = 0;
  const std::vector<Index> flat =
      pbd::largestFlatRegion(s.vertices, s.triangles, 2.0, 1e-3 * largestExtent(s.vertices), &flatArea);
  for (const pbd::Triangle& t : s.triangles)
    totalArea += 0.5 * (s.vertices[t[1]] - s.vertices[t[0]])
                           .cast<double>()
                           .cross((s.vertices[t[2]] - s.vertices[t[0]]).cast<double>())
                           .norm();
  if (flatArea < 0.02 * totalArea)
    fail(file,
         "a closed surface without a flat base; expected boundary loops at the mitral and aortic annuli or a "
         "flat truncated base");
  std::vector<Index> rest;
  for (Index f = 0; f < s.triangles.size(); ++f)
    if (!std::binary_search(flat.begin(), flat.end(), f)) rest.push_back(f);
  const pbd::SubSurface cut = pbd::extractSubSurface(s.vertices, s.triangles, rest);
  return {cut.vertices, cut.triangles};
}

}  // namespace

double metresPer(LengthUnit unit) { return unit == LengthUnit::Millimetre ? 1e-3 : 1.0; }
const char* unitName(LengthUnit unit) { return unit == LengthUnit::Millimetre ? "mm" : "m"; }

void checkHeartSize(double extent, LengthUnit unit, const std::string& file) {
  const double metres = extent * metresPer(unit);
  if (metres >= kSmallestHeart && metres <= kLargestHeart) return;
  const LengthUnit other = unit == LengthUnit::Millimetre ? LengthUnit::Metre : LengthUnit::Millimetre;
  const double otherMetres = extent * metresPer(other);
  std::string hint = "; check the file's units";
  if (otherMetres >= kSmallestHeart && otherMetres <= kLargestHeart)
    hint = "; is the file in " + std::string(unitName(other)) + "? (units = \"" + unitName(other) +
           "\" makes it " + format(otherMetres * 100) + " cm)";
  fail(file, "a heart " + format(extent) + " " + unitName(unit) + " across (" + format(metres * 100) +
                 " cm) is implausible; expected 3-30 cm" + hint);
}

WallResolution wallResolution(const std::string& name) {
  if (name == "coarse") return {0.006, 1};
  if (name == "default") return {0.005, 2};
  if (name == "fine") return {0.003, 3};
  throw std::invalid_argument("resolution '" + name + "': expected coarse, default or fine");
}

PatientWall buildPatientWall(const Surface& endocardium, const Surface* epicardium,
                             const PatientWallSettings& settings) {
  const std::string& file = settings.file;
  if (endocardium.triangles.empty()) fail(file, "no triangles; expected an endocardial surface");
  checkHeartSize(largestExtent(endocardium.vertices), settings.units, file);
  const double metresPerUnit = metresPer(settings.units);
  Surface s = inMetres(endocardium, metresPerUnit);
  checkTopology(s, file);
  std::vector<std::vector<Index>> loops = pbd::boundaryLoopVertices(s.triangles);
  if (loops.empty()) {
    s = withoutFlatBase(s, file);
    loops = pbd::boundaryLoopVertices(s.triangles);
  }
  if (loops.size() > 2)
    fail(file, std::to_string(loops.size()) +
                   " boundary loops; expected 2 (the mitral and aortic annuli) or 1 (a flat truncated base)");
  if (pbd::cappedSignedVolume(s.vertices, s.triangles) < 0)
    for (pbd::Triangle& t : s.triangles) std::swap(t[1], t[2]);  // face out of the cavity
  // A cavity: the surface, its loops closed flat, holds at least 1% of its extent cubed (a
  // ventricle holds 9-25%; a flat sheet or scattered triangles hold nothing).
  const double cavity = pbd::cappedSignedVolume(s.vertices, s.triangles), extent = largestExtent(s.vertices);
  if (cavity < 0.01 * extent * extent * extent)
    fail(file, "the surface holds " + format(cavity * 1e6) +
                   " mL with its loops closed flat, too little for a heart " + format(extent * 100) +
                   " cm across; expected a cup-shaped endocardium");
  std::vector<detail::LoopShape> shapes;
  for (const auto& loop : loops) shapes.push_back(detail::loopShape(s.vertices, loop));

  // The frame: base centre and septum.
  Vec3d baseCentre = shapes[0].centroid;
  Vec3d septumHint = Vec3d::Zero();
  std::size_t mitral = 0, aortic = 0;
  if (loops.size() == 2) {
    // By position: both annuli sit at the base, so their centroids lie close together along
    // the principal axis (biv-me: 5.9% of its length apart); a hole at the apex lies the length
    // of the ventricle away from the other loop.
    const Vec3d axis = principalAxis(s.vertices);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Vec3& p : s.vertices)
      lo = std::min(lo, axis.dot(p.cast<double>())), hi = std::max(hi, axis.dot(p.cast<double>()));
    const double apart = std::abs(axis.dot(shapes[0].centroid - shapes[1].centroid)) / (hi - lo);
    if (apart > 0.3)
      fail(file, "the 2 boundary loops lie " + format(100 * apart) +
                     "% of the ventricle's length apart; expected both annuli at the base (within 30%)");
    std::tie(mitral, aortic) = chooseAnnuli(shapes, settings);
    const double am = shapes[mitral].vectorArea.norm(), aa = shapes[aortic].vectorArea.norm();
    baseCentre = (am * shapes[mitral].centroid + aa * shapes[aortic].centroid) / (am + aa);
    septumHint = shapes[aortic].centroid - shapes[mitral].centroid;
  } else {
    if (settings.mitralLoop > 1 || settings.aorticLoop > 0)
      fail(file, settings.mitralLoopName + " or " + settings.aorticLoopName +
                     " given, but the surface has 1 boundary loop (a flat truncated base)");
    // An axisymmetric ventricle has no septum of its own: the file axis most across the long axis.
    const Vec3d axis = principalAxis(s.vertices);
    int across = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(axis[k]) < std::abs(axis[across])) across = k;
    septumHint = Vec3d::Unit(across);
  }
  const Vec3d y = longAxis(s, baseCentre);
  if (loops.size() == 2) {
    // The aortic root sits anteroseptally, not mid-septum: its centre is taken 45 degrees
    // anterior of the septum (about the long axis, anterior -> septal is a turn about -y).
    septumHint = Eigen::AngleAxisd(-kAorticToSeptumRad, y) * septumHint;
  }
  PatientWall wall;
  wall.septumFrom = loops.size() == 2 ? "aortic annulus" : "file axis";
  bool biventricularEpicardium = false;
  if (epicardium) {
    const Vec3d rv = rightVentricleSide(s, inMetres(*epicardium, metresPerUnit), y);
    biventricularEpicardium = rv.norm() > 0;
    if (biventricularEpicardium) septumHint = rv, wall.septumFrom = "right ventricle";
  }
  if (settings.septum) septumHint = *settings.septum, wall.septumFrom = "setting";
  wall.frame = frameOf(y, baseCentre, septumHint, metresPerUnit, file,
                       settings.septum ? settings.septumName : std::string("the septum direction"));
  for (Vec3& p : s.vertices)
    p = (wall.frame.rotation * (p.cast<double>() - wall.frame.origin)).cast<pbd::Real>();
  std::vector<Vec3d> annulusCentres;
  if (loops.size() == 2)
    for (std::size_t k : {mitral, aortic})
      annulusCentres.push_back(wall.frame.rotation * (shapes[k].centroid - wall.frame.origin));

  // Resolution.
  const pbd::RemeshedSurface remeshed =
      pbd::remeshIsotropic(s.vertices, s.triangles, {settings.resolution.edgeLength, 6});
  Surface surface{remeshed.vertices, remeshed.triangles};
  std::vector<bool> basePlate(surface.vertices.size(), false);
  const std::size_t inputLoops = loops.size();
  loops = pbd::boundaryLoopVertices(surface.triangles);
  // The annuli were found on the input's loops: a remesh that changed their number has lost
  // or made one (a fuzzed surface went from one loop to two and read annuli never found).
  if (loops.size() != inputLoops)
    fail(file, "remeshing to " + format(settings.resolution.edgeLength * 1e3) +
                   " mm changed the boundary loops from " + std::to_string(inputLoops) + " to " +
                   std::to_string(loops.size()) + "; expected a finer resolution");
  if (loops.size() == 1) {
    detail::OpenedBase opened = detail::openFlatBase(surface, loops[0], settings.resolution.edgeLength, file);
    surface = std::move(opened.surface);
    basePlate = std::move(opened.basePlate);
    wall.mitralRing = std::move(opened.mitralRing);
    wall.aorticRing = std::move(opened.aorticRing);
    wall.baseOpened = true;
  } else if (loops.size() == 2) {
    // The remeshed loops, matched to the annuli by their centroids.
    const Vec3d c0 = detail::loopShape(surface.vertices, loops[0]).centroid;
    const bool firstIsMitral = (c0 - annulusCentres[0]).norm() <= (c0 - annulusCentres[1]).norm();
    wall.mitralRing = loops[firstIsMitral ? 0 : 1];
    wall.aorticRing = loops[firstIsMitral ? 1 : 0];
  } else {
    fail(file, "remeshing to " + format(settings.resolution.edgeLength * 1e3) +
                   " mm changed the boundary loops to " + std::to_string(loops.size()) +
                   "; expected a finer resolution");
  }

  // Thickness and extrusion.
  pbd::ExtrusionSettings extrusion;
  extrusion.layers = settings.resolution.layers;
  std::vector<double> thickness(surface.vertices.size(), settings.wallThickness);
  wall.thicknessFromEpicardium = epicardium && !biventricularEpicardium;
  if (wall.thicknessFromEpicardium) {
    Surface epi = inMetres(*epicardium, metresPerUnit);
    for (Vec3& p : epi.vertices)
      p = (wall.frame.rotation * (p.cast<double>() - wall.frame.origin)).cast<pbd::Real>();
    thickness = pbd::thicknessToSurface(surface.vertices,
                                        pbd::offsetDirections(surface.vertices, surface.triangles, extrusion),
                                        epi.vertices, epi.triangles);
  }
  if (wall.baseOpened) {
    std::vector<double> cup;
    for (std::size_t i = 0; i < thickness.size(); ++i)
      if (!basePlate[i]) cup.push_back(thickness[i]);
    std::nth_element(cup.begin(), cup.begin() + static_cast<std::ptrdiff_t>(cup.size() / 2), cup.end());
    for (std::size_t i = 0; i < thickness.size(); ++i)
      if (basePlate[i]) thickness[i] = kBaseThicknessShare * cup[cup.size() / 2];
  }
  pbd::ExtrudedWall extruded;
  try {
    extruded = pbd::extrudeWall(surface.vertices, surface.triangles, thickness, extrusion);
  } catch (const std::runtime_error& e) {
    fail(file, std::string("cannot build the wall: ") + e.what());
  }
  restoreCavityVolume(surface, extruded.mesh, pbd::cappedSignedVolume(s.vertices, s.triangles));
  wall.mesh = std::move(extruded.mesh);
  wall.endoVertices = surface.vertices.size();
  wall.endocardium = surface.triangles;
  wall.basePlate = std::move(basePlate);
  wall.shrunkVertices = extruded.shrunkVertices;
  wall.quality = pbd::measureQuality(wall.mesh);
  wall.cavityVolume = pbd::cappedSignedVolume(surface.vertices, surface.triangles);
  for (const Vec3& p : surface.vertices) wall.cavityLength = std::max(wall.cavityLength, -double(p.y()));
  wall.segment = detail::patientAhaSegments(wall);
  return wall;
}

}  // namespace hs::cardiac
