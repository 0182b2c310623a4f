// A machine profile's part in how the motion interpreter reads its programs (tape/motion.hpp).
#include "tape/machine.hpp"
#include "tape/motion.hpp"

namespace tape {

MotionOptions motion_options(const MachineProfile& m, Dialect d) {
    MotionOptions o = motion_options(d);  // the arc tolerance of the dialect's controls
    o.lathe = m.kind == MachineKind::lathe;
    o.diameter = m.diameter_programming;
    if (!m.format.words.empty()) o.spec = &m.format;
    if (m.arc_tolerance_mm > 0 || m.arc_tolerance_relative > 0) {
        o.arc_tolerance_mm = m.arc_tolerance_mm;
        o.arc_tolerance_relative = m.arc_tolerance_relative;
        o.arc_tolerance_linuxcnc = false;
    }
    return o;
}

}  // namespace tape
