// The floor calibration of a recording, for `sightline-cli floor` (the mapping pipeline
// calibrates its floor the same way, with FloorCalibrator, on its first frames).
#pragma once

#include <string>

#include "core/common/status.h"
#include "core/mapping/floor_types.h"

namespace sightline {

// Calibrates the floor from the first `frames` frames of an RGB-D dataset or the clouds of a
// PCD file/folder. `used_frames` receives the number of frames read.
StatusOr<FloorFitResult> CalibrateFloorFromDataset(const std::string& path, int frames,
                                                   const FloorPlaneOptions& options,
                                                   int* used_frames = nullptr);

}  // namespace sightline
