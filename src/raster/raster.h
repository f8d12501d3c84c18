// Umbrella header for the rasterizer's public API (what the CLI includes).
#pragma once

#include "raster/camera.h"
#include "raster/draw_mesh.h"
#include "raster/image.h"
#include "raster/png_writer.h"
#include "raster/render.h"
#include "raster/srgb.h"
