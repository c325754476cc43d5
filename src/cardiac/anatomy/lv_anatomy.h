#pragma once
// The anatomical sizes a cardiologist checks first, measured on a model's rest mesh (not read
// back from its parameters), so that procedural and patient hearts are measured alike:
// the valve annuli's areas, the aortic root's diameter and the ventricle's long axis.
// Reference adult values (issue 15): mitral annulus 4-6 cm^2, aortic annulus 3-4 cm^2, aortic
// root 30-34 mm, long axis 8-9 cm at end-diastole.
#include <optional>

#include "cardiac/anatomy/lv_model.h"

namespace hs::cardiac {

struct AnatomyFigures {
  double mitralArea = 0;  // m^2, the mitral ring's polygon
  double aorticArea = 0;  // m^2, the aortic ring's polygon
  // m, twice the largest distance of the outflow vessel's lumen from the aortic ring's axis;
  // none on a model without an outflow vessel.
  std::optional<double> aorticRootDiameter;
  // m, from the mitral annulus's plane to the farthest point of the cavity along the annulus's
  // normal (the endocardial apex): the echocardiographer's LV length.
  double longAxis = 0;
};

AnatomyFigures measureAnatomy(const LvModel& model);

}  // namespace hs::cardiac
