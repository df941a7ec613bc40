#pragma once
// What the RS4 puts into COM_CMD_MESS_16_RT 0x23 ([RS4 manual §5.2.3.4];
// [RS4 manual §5.2.3.4], table 5.2-14): the values of segments start, start+res, …, stop (stop
// always), each a distance in mm whose bit 0 says "the contour violated a protective field between
// this value and the previous one". The bytes are rs4/protocol's job; this computes the flagged
// values from a scan.

#include "rs4/scanner/field_evaluation.h"
#include "rs4/scanner/parameter_set.h"

#include <cstdint>

namespace rs4sim::rs4::scanner {

struct ScanResult;

// A 529-value contour ready for the telegram: every segment holds (mm & 0xFFFE) | flag.
// For an output segment the flag covers the segments after the previous output value up
// to and including this one (the first output value: its own segment); other segments
// carry their own flag. "Protective field" = the active pair, and during a switch-over
// also the pair being left. An invalid window (resolution 0, start > stop, stop > 528)
// leaves every segment with its own flag.
Contour measurement_contour(const Contour& contour, const SegmentFlags& protective,
                            const MeasurementOutput& window) noexcept;
Contour measurement_contour(const ScanResult& scan, const MeasurementOutput& window) noexcept;

}  // namespace rs4sim::rs4::scanner
