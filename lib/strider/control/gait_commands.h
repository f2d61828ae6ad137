//! The gait commands and their replies, applied to a motion sink: `gait
//! NAME`, `set PARAM VALUE` and `get`.
#ifndef STRIDER_CONTROL_GAIT_COMMANDS_H
#define STRIDER_CONTROL_GAIT_COMMANDS_H

#include <stdint.h>
#include <string.h>

#include "../gait/gait_presets.h"
#include "../gait/gait_tuning.h"
#include "command.h"
#include "reply_texts.h"
#include "robot_mode.h"

namespace strider {

//! The gait presets of the model called `robot` (gait_presets.h; those the
//! build of model index kModel keeps), each after a space.
template <uint8_t kModel = kEveryModel>
void write_gait_presets(ReplyWriter& w, const char* robot) {
  GaitPreset p;
  for (uint8_t i = 0; robot != nullptr && gait_preset_at<kModel>(i, &p); ++i)
    if (strcmp(p.robot, robot) == 0) w.ch(' ').text(p.name);
}

template <typename Sink>
void apply_gait(Sink& sink, const Command& c, ReplyWriter& w) {
  if (!sink.set_gait(c.word)) {
    write_error(w, ControlError::kUnknownGait, FlashText{text::kUnknownGait_});
    sink.write_gait_names(w);
    return;
  }
  w.text(FlashText{text::kOkGait_}).text(c.word);
}

//! `set PARAM VALUE`: `ok set step_height 15.00`, or err 25 with the range.
template <typename Sink>
void set_tuning(Sink& sink, const Command& c, ReplyWriter& w) {
  const TuneParam p = TuneParam(c.arg[0]);
  const FlashText name = flash_name(kTuneParamNames, kTuneParamCount, uint8_t(p));
  if (!sink.tune(p, c.arg[1])) {
    const TuneRange r = sink.tune_range(p);
    write_error(w, ControlError::kTuneRefused, name);
    if (p != TuneParam::kSwing) {
      w.text(FlashText{text::kOutOfRange_}).hundredths(r.lo).ch('.').ch('.').hundredths(r.hi);
      return;
    }
    w.text(FlashText{text::kNotWithin_});
    for (uint8_t k = 0, n = 0; k < kSwingShapeCount; ++k)
      if ((r.lo >> k) & 1) (n++ != 0 ? w.ch(' ') : w).text(flash_name(kSwingShapeNames, kSwingShapeCount, k));
    return;
  }
  w.text(FlashText{text::kOkSet_}).text(name).ch(' ');
  if (p == TuneParam::kSwing) w.text(flash_name(kSwingShapeNames, kSwingShapeCount, uint8_t(c.arg[1])));
  else w.hundredths(c.arg[1]);
}

//! `get`: the gait and its live parameters.
template <typename Sink>
void get_tuning(Sink& sink, ReplyWriter& w) {
  w.text(FlashText{text::kOkGet}).field_text(FlashText{text::kGaitKey}, sink.gait_name());
  sink.write_tuning(w);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_GAIT_COMMANDS_H
