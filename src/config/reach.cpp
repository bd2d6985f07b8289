#include "config/reach.h"

#include "lpe/analysis.h"

namespace lightpath {

Reach reachOf(const IntegratorInfo& integrator, const std::string& pathClass) {
    Reach reach;
    reach.areaLights = lpe::haveCommonPath({pathClass, integrator.pathLanguage});
    reach.pointLights = lpe::haveCommonPath({pathClass, integrator.pathLanguage, integrator.pointLightLanguage});
    return reach;
}

}  // namespace lightpath
