/**
 * @file    penumbraShadowInputs.h
 * @brief   A record of what one frame's light-intensity layers were drawn from, so that a frame
 *          in which none of it changed composites those layers again instead of redrawing them
 *          (vtkSoftShadowPass::ReuseUnchangedShadows).
 *
 * The layers depend on the viewport, the camera the shadows are drawn with, each shadowing light
 * and its samples, the pass's settings, and the depth and shape of every prop that the depth pass
 * draws or that casts. Values are recorded where VTK does not mark a change (vtkCamera::DeepCopy
 * does not modify the camera; a prop's matrix can change through its user transform; colours,
 * which move an actor's and a mapper's times, change no shadow, so the look and mapper settings
 * that can are recorded by value where the classes are VTK's own), and modification times
 * elsewhere: each prop, its mapper with its clipping planes and shader property, and every input
 * data object of the mapper (each block of composite data), brought up to date first
 * (UpdateMapperInputs). Props outside the shadows (neither a vtkProp3D nor a vtkPropAssembly:
 * 2D props, widget representations, captions) are left out: they neither cast nor receive. A
 * prop whose changes cannot be seen this way (a vtkLODActor or vtkLODProp3D, which pick their
 * level by render time, or a mapper with an UpdateShaderEvent observer, which may move vertices
 * through uniforms) makes every frame draw its shadows.
 */
#ifndef penumbraShadowInputs_h
#define penumbraShadowInputs_h

#include "vtkType.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

class vtkProp;
class vtkRenderer;

namespace penumbra
{

class ShadowInputs
{
public:
  /// Starts recording a frame's inputs.
  void Begin();
  void Add(const void* object);
  void Add(double value);
  void Add(const glm::dmat4& matrix);
  void Add(const glm::dvec4& vector);
  /// The world-to-clip matrix the shadows are drawn with. It matches the kept frame's where each
  /// entry is within 1e-7 of its row's largest, which moves no point by more than about 1e-4 of a
  /// pixel: vtkWindowToImageFilter draws a screenshot with a copy of the camera whose view angle
  /// went through a float, and that frame reuses the shadows.
  void SetWorldToClip(const glm::dmat4& worldToClip) { this->WorldToClip = worldToClip; }
  void AddTime(vtkMTimeType time);
  /// vtkMapper's static coincident-topology settings.
  void AddCoincidentTopologySettings();
  /// Adds every prop of `renderer`'s that can draw depth or cast (not those OutsideTheShadows),
  /// with its matrices, mapper and input data (as UpdateMapperInputs left it). False when one of
  /// them can change without any of that changing: the frame must then be drawn.
  bool AddProps(vtkRenderer* renderer);

  /// Whether the inputs recorded since Begin equal those of the last frame passed to Keep.
  bool MatchKept() const;
  /// The frame recorded since Begin was drawn: its layers are the ones a later frame may reuse.
  void Keep();
  /// The kept layers are gone or stale (graphics resources released, a frame without shadows).
  void Forget();

private:
  /// Adds the leaf of each of `prop`'s assembly paths; false as AddProps.
  bool AddPaths(vtkProp* prop);
  /// `part`: the leaf of an assembly's path, drawn with the path's matrix.
  bool AddLeaf(vtkProp* leaf, const double* pathMatrix, bool part);
  std::vector<std::uint64_t> Current;
  std::vector<std::uint64_t> Kept;
  glm::dmat4 WorldToClip{ 0.0 };
  glm::dmat4 KeptWorldToClip{ 0.0 };
  bool HaveKept = false;
};

/// Runs what feeds the mappers and textures of `renderer`'s visible props (not those
/// OutsideTheShadows), each input's producer as VTK's polydata mapper runs it while it draws
/// (vtkOpenGLPolyDataMapper's
/// RenderPiece), before anything of the frame's shadows reads the props' data or bounds: a source
/// changed since the last frame has not run yet, and a time step requested through a mapper's
/// input information (UPDATE_TIME_STEP) runs only so, not through the mapper's own Update. Other
/// mappers may not run it (vtkDataSetMapper draws through a surface filter of its own), so with
/// the pass such a step is drawn where VTK alone may keep an older one.
void UpdateMapperInputs(vtkRenderer* renderer);

} // namespace penumbra

#endif
