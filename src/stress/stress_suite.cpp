#include "stress/stress_suite.h"

#include "stress/bvh_row.h"
#include "stress/emitter_rows.h"
#include "stress/mesh_rows.h"
#include "stress/non_finite_row.h"
#include "stress/render_row.h"
#include "stress/shadow_rows.h"
#include "stress/sphere_rows.h"

namespace lightpath {

std::vector<ScoreRow> runStressSuite(const StressConfig& config) {
    std::vector<ScoreRow> rows;
    runSphereRows(config, rows);
    runMeshRows(config, rows);
    runShadowRows(config, rows);
    runBvhRow(config, rows);
    runNonFiniteRow(config, rows);
    runEmitterRows(config, rows);
    runRenderRow(config, rows);
    return rows;
}

}  // namespace lightpath
