/**
 * @file   penumbraLayeredTexture.h
 * @brief  A vtkTextureObject holding a 2D array texture, one layer per light or counter word.
 *
 * The light-intensity layers and the sample counters were 3D textures, which stop at
 * GL_MAX_3D_TEXTURE_SIZE (2048 on llvmpipe and on many integrated GPUs): a 4K frame, or a frame
 * of a 920-pixel window supersampled by vtkSSAAPass, had no shadows. A 2D array's layers are as
 * wide and tall as 2D textures (GL_MAX_TEXTURE_SIZE, 16384 on llvmpipe). VTK 9.1's
 * vtkTextureObject allocates no such texture and its framebuffer object attaches a layer of one
 * as a 3D slice: this class allocates it and attaches a layer itself.
 */
#ifndef penumbraLayeredTexture_h
#define penumbraLayeredTexture_h

#include "vtkTextureObject.h"

/// A 2D array texture (GL_TEXTURE_2D_ARRAY); otherwise a vtkTextureObject (activation, binding,
/// parameters, Download) whose depth is its layer count.
class vtkPenumbraLayeredTexture : public vtkTextureObject
{
public:
  static vtkPenumbraLayeredTexture* New();
  vtkTypeMacro(vtkPenumbraLayeredTexture, vtkTextureObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Allocates `layers` layers of width x height texels of `components` of `vtkType` (or of
  /// the internal format, format and type set before), as vtkTextureObject::Allocate3D does for
  /// a 3D texture. False, with nothing held, when OpenGL refuses it: a 4K frame's counters for
  /// 256 samples (2 GB) are GL_OUT_OF_MEMORY on llvmpipe, which vtkTextureObject would not tell.
  bool AllocateLayers(
    unsigned int width, unsigned int height, unsigned int layers, int components, int vtkType);

  /// Attaches layer `layer` as colour attachment `index` of the framebuffer bound for drawing.
  void AttachLayer(unsigned int index, int layer);

protected:
  vtkPenumbraLayeredTexture() = default;
  ~vtkPenumbraLayeredTexture() override = default;

private:
  vtkPenumbraLayeredTexture(const vtkPenumbraLayeredTexture&) = delete;
  void operator=(const vtkPenumbraLayeredTexture&) = delete;
};

#endif
