#include "app/sightline/core_texts.h"

#include <QCoreApplication>

namespace sightline {

namespace {

// Copied word for word from core/sensors/driver_registry.cpp (DriverInfo::description).
const char* const kCoreTexts[] = {
    QT_TRANSLATE_NOOP("sightline::CoreText",
                      "OpenNI2 RGB-D cameras (Kinect, Xtion, Carmine) and .oni recordings"),
    QT_TRANSLATE_NOOP("sightline::CoreText",
                      "GigE Vision / USB3 Vision cameras through Aravis: one camera, or a stereo "
                      "pair as aravis://LEFT_ID,RIGHT_ID"),
    QT_TRANSLATE_NOOP("sightline::CoreText", "USB webcams through OpenCV's V4L2 backend"),
    QT_TRANSLATE_NOOP("sightline::CoreText",
                      "A recording played as a live camera (replay://PATH?fps=30&loop=1)"),
    QT_TRANSLATE_NOOP(
        "sightline::CoreText",
        "ROS 1 bag files (.bag): images, RGB-D, stereo and point clouds, with tf ground truth"),
};

}  // namespace

QString CoreText(const std::string& english) {
  return QCoreApplication::translate("sightline::CoreText", english.c_str());
}

std::vector<std::string> KnownCoreTexts() { return {std::begin(kCoreTexts), std::end(kCoreTexts)}; }

}  // namespace sightline
