// Layered materials (MaterialDesc::layered; POV-Ray's layered textures): what one layer shows
// at a surface point. The Whitted integrator shades every layer and adds them, each weighted
// by what the coats above it let through; the path tracer picks one layer per hit, with the
// probability of the share it shows, which has the same mean.
#pragma once

#include <vector>

#include "render/shade/shading.hpp"

namespace rts::render {

// The coat `layer` at a hit, as the Whitted integrator shades it (written into `scratch`): its
// colour looked up there (a pattern's colour map gives colour and transmit at once), its
// diffuse, ambient and emission weighted by its cover 1 - max(through) (POV-Ray's layer
// attenuation; its highlight and reflection keep their weights, so a clear varnish still
// shines), and nothing passing into the object (a coat's transmit shows the layers below).
// `through`: what it lets through to them, its own `transmit` plus its colour map's, at most 1.
const MaterialDesc& coat_at(const MaterialDesc& layer, const World& world, const WorldHit& hit,
                            const std::vector<CompiledTexture>& textures, MaterialScratch& scratch, Rgb& through);

// The layered material a hit on material `id` shows, resolving choices by pattern on the way;
// kNoId when what it shows is not layered.
MaterialId layered_at(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                      const WorldHit& hit, const std::vector<CompiledTexture>& textures);

// Path mode: the material a hit on material `id` shows (as surface_material_id), except that a
// layered one gives one of its layers, picked with u in [0, 1) by its share, from the top:
// a = min(1, cover + gloss) of what the coats above leave (cover = 1 - max(through), untinted;
// gloss = specular + max(reflect)), the base the rest. A picked coat is coat_at's colour with
// its diffuse weighted by cover / a and its gloss by 1 / a, so the mixture's mean is each
// coat's diffuse by its cover plus its gloss whole, as the Whitted sum; nothing passes through
// it. `picked`: the id of the layer picked (for per-material scales), or the resolved id. The
// result may live in `scratch`.
const MaterialDesc& path_layer(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                               const WorldHit& hit, const std::vector<CompiledTexture>& textures, double u,
                               MaterialScratch& scratch, const MaterialDesc& fallback, MaterialId& picked);

}  // namespace rts::render
