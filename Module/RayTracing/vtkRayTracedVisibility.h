/**
 * @class   vtkRayTracedVisibility
 * @brief   Ray-traced ground truth of the light visibility that vtkSoftShadowPass approximates.
 *
 * For every pixel of a renderer's viewport this class traces a primary ray (through the pixel
 * centre, with VTK's own camera matrices so that pixels line up with the rasterized image) into
 * the renderer's opaque actors and, at the surface point it hits, estimates which fraction of
 * each shadowing light that point sees, with shadow rays traced by Embree:
 *
 * - the lights are those for which vtkSoftShadowPass::LightCastsShadows() is true, with the size
 *   given by vtkSoftShadowPass::GetLightRadius(): a sphere of that radius (world units) for a
 *   positional light, a cone of that angular radius (degrees) for a directional one; a light of
 *   radius 0 is a point (or a single direction) and gives 0 or 1;
 * - the light is sampled uniformly over the solid angle it subtends from the surface point,
 *   SamplesPerLight stratified samples, jittered by a random generator seeded from (Seed, pixel,
 *   light) so that results do not depend on the number of threads;
 * - every visible actor with opacity 1 is seen by primary rays; only those for which
 *   vtkSoftShadowPass::GetCastsShadows() is true block shadow rays; triangles occlude from both
 *   sides, and a light sample below the surface's own plane counts as blocked;
 * - primary rays pass through what VTK does not draw: the clipped side of a mapper's clipping
 *   planes, and the faces a property culls (front or back: counter-clockwise or clockwise as the
 *   eye sees them); shadow rays pass through clipped parts only, as culling hides faces from
 *   the eye, not from the light;
 * - translucent actors and blocks (opacity in (0, 1)) are not seen by primary rays; a shadow ray
 *   that no opaque caster blocks is multiplied by 1 - opacity at each of their triangles it
 *   crosses (every hit, traced on past the last), as transmission.
 *
 * A surface point inside a positional light's sphere sees all of that light.
 *
 * Results are one-component float images of the viewport's size (VTK image order: row 0 at the
 * bottom, as glReadPixels): one visibility image per light (background pixels 1) and one depth
 * image holding the window depth the OpenGL depth buffer would hold (background 1), so that
 * callers can compare with vtkSoftShadowPass only where both saw the same surface.
 *
 * It is meant for tests and for judging the shadow pass, not for interactive use: Update()
 * rebuilds the ray-tracing scenes every time.
 *
 * @sa vtkSoftShadowPass
 */
#ifndef vtkRayTracedVisibility_h
#define vtkRayTracedVisibility_h

#include "vtkObject.h"
#include "vtkPenumbraRayTracingModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkRenderer;

class VTKPENUMBRARAYTRACING_EXPORT vtkRayTracedVisibility : public vtkObject
{
public:
  static vtkRayTracedVisibility* New();
  vtkTypeMacro(vtkRayTracedVisibility, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The renderer whose viewport, camera, lights and actors are traced. Render its window once
   * before Update() so that the camera's clipping range and the tiled viewport size are set.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  ///@{
  /**
   * Shadow rays per pixel for each light with a radius above 0 (default 64). A light of radius 0
   * always uses one ray.
   */
  vtkSetClampMacro(SamplesPerLight, int, 1, 65536);
  vtkGetMacro(SamplesPerLight, int);
  ///@}

  ///@{
  /**
   * Seed of the sample jitter (default 1). The same seed gives the same images.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Threads tracing the rows of the image; 0 (the default) uses every core.
   */
  vtkSetMacro(NumberOfThreads, int);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Traces the renderer's scene. Returns false when there is no renderer, no camera or the
   * viewport is empty. Fires vtkCommand::ProgressEvent with a double in [0, 1] as rows finish.
   */
  bool Update();

  /**
   * Fraction of the lightIndex-th light of the renderer's light collection seen by the surface at
   * each pixel (1 for background pixels), as a one-component float image of the viewport's size;
   * nullptr for a light that casts no shadow or an index out of range. Valid after Update().
   */
  vtkImageData* GetVisibilityImage(int lightIndex);

  /**
   * Window depth in [0, 1] of the surface at each pixel as the OpenGL depth buffer holds it
   * (1 for background), as a one-component float image of the viewport's size. Valid after
   * Update().
   */
  vtkImageData* GetDepthImage();

  /**
   * Triangles traced (seen by primary rays) and, among them, those that block shadow rays, in the
   * last Update().
   */
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  vtkGetMacro(NumberOfCasterTriangles, vtkIdType);

  /**
   * Lights for which a visibility image was computed in the last Update().
   */
  vtkGetMacro(NumberOfShadowingLights, int);

protected:
  vtkRayTracedVisibility();
  ~vtkRayTracedVisibility() override;

  vtkRenderer* Renderer = nullptr;
  int SamplesPerLight = 64;
  unsigned int Seed = 1;
  int NumberOfThreads = 0;
  vtkIdType NumberOfTriangles = 0;
  vtkIdType NumberOfCasterTriangles = 0;
  int NumberOfShadowingLights = 0;

private:
  /// The renderer's tiled viewport size, or false (an error reported) when there is nothing to
  /// trace: no renderer or window, an empty viewport, no camera.
  bool CheckRenderer(int& width, int& height);

  vtkRayTracedVisibility(const vtkRayTracedVisibility&) = delete;
  void operator=(const vtkRayTracedVisibility&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
