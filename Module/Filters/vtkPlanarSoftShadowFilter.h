/**
 * @class   vtkPlanarSoftShadowFilter
 * @brief   The soft shadow of polygonal casters on a plane, as triangles with light intensity.
 *
 * The input is the casters' polydata (polygons and triangle strips, world coordinates). The
 * filter samples the area light (LightSamples points of a disk of LightRadius for a positional
 * light, directions of a cone of LightRadius degrees for a directional one, the conventions of
 * vtkSoftShadowPass::SetLightRadius), computes the hard shadow of every sample on the plane
 * (PlaneOrigin, PlaneNormal) as the union of the projected caster polygons, and merges the N
 * hard shadows into nested regions L_k, the points covered by at least k of them. The boundaries
 * of L_k are the rings of the soft shadow: L_N is the umbra, L_1 minus L_N the penumbra. The
 * region is triangulated with every ring as a constraint (CGAL's constrained Delaunay
 * triangulation, refined so that triangles are not long and thin) and each penumbra vertex gets
 * the mean coverage of an infinitesimal disk around it, so that intensity is interpolated
 * linearly between rings.
 *
 * Output: triangles on the plane, lifted by Offset along the normal, with
 * - point data "LightIntensity" (float, [0, 1]: 0 umbra, 1 lit), the fraction of the light a
 *   point sees; umbra triangles are flat 0 and lit triangles flat 1 (they have their own points);
 * - cell data "ShadowRegion" (unsigned char): 0 umbra, 1 penumbra, 2 lit (lit triangles only
 *   with OutputLitRegion on: a margin around the shadow, so that the output can be drawn as a
 *   decal that covers the shadow's surroundings).
 *
 * After an update, GetUmbraArea(), GetPenumbraArea() and GetShadowIntegral() (the integral of
 * 1 - LightIntensity over the output, the shadow's "darkness area") measure the shadow.
 *
 * Robustness: polygon booleans run on integers (Clipper) at a scale that resolves about 1e-9 of
 * the shadow's extent; triangles are clipped to the part strictly above the plane and, for a
 * positional light, below 99% of each sample's height so that nothing projects to infinity;
 * points with non-finite coordinates are dropped with a warning; refinement is bounded. See
 * Documentation/planar_filter.md for the algorithm, complexity and measured accuracy.
 *
 * @sa vtkSoftShadowPass vtkRayTracedVisibility
 */
#ifndef vtkPlanarSoftShadowFilter_h
#define vtkPlanarSoftShadowFilter_h

#include "vtkPenumbraFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPENUMBRAFILTERS_EXPORT vtkPlanarSoftShadowFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkPlanarSoftShadowFilter* New();
  vtkTypeMacro(vtkPlanarSoftShadowFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Light sample patterns over the disk (or cone) of the light.
  enum SamplePatterns
  {
    SUNFLOWER = 0, ///< Vogel's sunflower, as vtkSoftShadowPass: equal-area, golden-angle turns
    POLAR_GRID = 1 ///< concentric equal-area rings, evenly spaced samples on each
  };

  ///@{
  /**
   * Position of a positional light, or (Positional off) the direction towards a directional
   * light. Default (0, 0, 1).
   */
  vtkSetVector3Macro(LightPosition, double);
  vtkGetVector3Macro(LightPosition, double);
  ///@}

  ///@{
  /**
   * Whether the light is positional (default) or directional.
   */
  vtkSetMacro(Positional, bool);
  vtkGetMacro(Positional, bool);
  vtkBooleanMacro(Positional, bool);
  ///@}

  ///@{
  /**
   * Radius of the light: world units for a positional light (a disk facing the casters), an
   * angular radius in degrees for a directional one, as vtkSoftShadowPass::SetLightRadius.
   * 0 (the default) is a point light: one sample, a hard shadow.
   */
  vtkSetClampMacro(LightRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightRadius, double);
  ///@}

  ///@{
  /**
   * Number of light samples, N (default 32). Intensity takes N + 1 levels between rings.
   * Work grows as N times the casters' size plus N^2 polygon operations on the rings.
   */
  vtkSetClampMacro(LightSamples, int, 1, 1024);
  vtkGetMacro(LightSamples, int);
  ///@}

  ///@{
  /**
   * Pattern of the light samples (default SUNFLOWER).
   */
  vtkSetClampMacro(SamplePattern, int, SUNFLOWER, POLAR_GRID);
  vtkGetMacro(SamplePattern, int);
  void SetSamplePatternToSunflower() { this->SetSamplePattern(SUNFLOWER); }
  void SetSamplePatternToPolarGrid() { this->SetSamplePattern(POLAR_GRID); }
  ///@}

  ///@{
  /**
   * A point of the receiving plane (default origin) and its normal (default (0, 0, 1)), which
   * points towards the light.
   */
  vtkSetVector3Macro(PlaneOrigin, double);
  vtkGetVector3Macro(PlaneOrigin, double);
  vtkSetVector3Macro(PlaneNormal, double);
  vtkGetVector3Macro(PlaneNormal, double);
  ///@}

  ///@{
  /**
   * Lift of the output along the plane normal (default 0), so that it can be drawn as a decal
   * on the receiver without z-fighting.
   */
  vtkSetMacro(Offset, double);
  vtkGetMacro(Offset, double);
  ///@}

  ///@{
  /**
   * Whether lit triangles (intensity 1) around the shadow are output too (default off). The lit
   * region is the rectangle of the shadow's bounds grown by LitMargin times its size.
   */
  vtkSetMacro(OutputLitRegion, bool);
  vtkGetMacro(OutputLitRegion, bool);
  vtkBooleanMacro(OutputLitRegion, bool);
  vtkSetClampMacro(LitMargin, double, 0.0, 10.0);
  vtkGetMacro(LitMargin, double);
  ///@}

  ///@{
  /**
   * Whether the triangulation is refined against long, thin triangles that would stretch one
   * intensity across the penumbra (Mach bands), default on. In up to 8 rounds, ring edges that a
   * neighbouring vertex sees at more than 90 degrees are split and penumbra triangles with an
   * angle under 20 degrees get their centroid; at most MaximumRefinementPoints points are added
   * (default 5000).
   */
  vtkSetMacro(Refine, bool);
  vtkGetMacro(Refine, bool);
  vtkBooleanMacro(Refine, bool);
  vtkSetClampMacro(MaximumRefinementPoints, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumRefinementPoints, int);
  ///@}

  ///@{
  /**
   * Measures of the last output, in the plane's units squared: area of the umbra triangles, of
   * the penumbra triangles, and the integral of 1 - LightIntensity over the output (exact for
   * the linear interpolation, so the area of a hard shadow of the same total darkness).
   */
  vtkGetMacro(UmbraArea, double);
  vtkGetMacro(PenumbraArea, double);
  vtkGetMacro(ShadowIntegral, double);
  ///@}

  /// Light samples used in the last update (those above the plane).
  vtkGetMacro(NumberOfUsedSamples, int);

protected:
  vtkPlanarSoftShadowFilter();
  ~vtkPlanarSoftShadowFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  double LightPosition[3] = { 0.0, 0.0, 1.0 };
  bool Positional = true;
  double LightRadius = 0.0;
  int LightSamples = 32;
  int SamplePattern = SUNFLOWER;
  double PlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double PlaneNormal[3] = { 0.0, 0.0, 1.0 };
  double Offset = 0.0;
  bool OutputLitRegion = false;
  double LitMargin = 0.1;
  bool Refine = true;
  int MaximumRefinementPoints = 5000;

  double UmbraArea = 0.0;
  double PenumbraArea = 0.0;
  double ShadowIntegral = 0.0;
  int NumberOfUsedSamples = 0;

private:
  vtkPlanarSoftShadowFilter(const vtkPlanarSoftShadowFilter&) = delete;
  void operator=(const vtkPlanarSoftShadowFilter&) = delete;
};

#endif
