// Shadow maps sized by need: a local light of limited range gets the texels its lit part of
// the picture can use, not the default 2048², and the frame's maps are held to what the driver
// can store (Godot 4's shadow atlas and Unity HDRP's cached shadows size local lights' maps by
// their screen coverage the same way). Pure: no GL.
#pragma once

#include <cstddef>

#include "gnomon/Scene.h"
#include "shadow/FramePlan.h"

namespace gnomon::shadow {

// The smallest size by need: below it a spot's cone or a face holds too few texels for its
// filter's footprint.
constexpr int kMinNeededMapSize = 128;
// Map texels per picture pixel across the light's reach on screen.
constexpr float kNeededTexelsPerPixel = 2.0f;

// Sizes by need go up in half octaves from kMinNeededMapSize: 128, 180, 256, 360, 512, 724,
// 1024... (between powers of two, 2^(k/2) rounded down to a multiple of 4, so two fit the
// slots of a layer twice their size). Step k's size.
int neededSizeStep(int k);

// The map size a point or spot light with a range needs in a width x height picture from
// `view`: kNeededTexelsPerPixel times the pixels its range's sphere spans on screen, rounded up
// to a step of neededSizeStep, within [kMinNeededMapSize, largest]; `largest` when the camera is
// inside the sphere. 0 (the light's own size) for other lights and lights without a range.
int neededMapSize(const Light& light, const Camera& view, int width, int height, int largest);

// A map fitted to part of a face or cone (the part the view sees) keeps the density of the whole
// face or cone at the needed size with fewer texels: `size` halved as often as its texels stay
// at most `wholeTexel` wide and it stays at least kMinNeededMapSize, for a frame fitted at
// `size` whose texels are `fittedTexel` wide (both in tan units, at distance 1). `held`: the size
// an earlier frame kept, reused while it lies in that range, so a moving view does not flip
// between sizes (0: none).
int windowMapSize(float fittedTexel, float wholeTexel, int size, int held);

// The bytes a layout's two arrays take (2D maps, cubes), the larger of the two.
std::size_t largestArrayBytes(const MapLayout& layout);

}  // namespace gnomon::shadow
