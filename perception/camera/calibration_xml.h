#pragma once
// Our reader of OpenCV calibration files in XML (as cv::FileStorage writes them), with TinyXML.
// It replaces cv::FileStorage for reading them because OpenCV 4.6's XML parser dereferences a
// null pointer on some malformed files (a 14-byte one, "<?xml versign=", found by fuzzing).
//
// Read: the root <opencv_storage>; its children image_width and image_height (positive
// integers), camera_matrix (or cameraMatrix, K) and distortion_coefficients (or dist_coeffs,
// distCoeffs, D), each with <rows>, <cols> and <data> (rows x cols numbers separated by
// spaces; <dt> is not looked at). Other elements are ignored. At most 4 MiB.
#include <string>

#include "perception/camera/calibration_yaml.h"  // OpenCvCalibration

namespace demoplan::perception {

// Throws InputError naming the file and the element (one line).
OpenCvCalibration read_calibration_xml(const std::string& path);

}  // namespace demoplan::perception
