// Pca9685Output: the firmware's ServoOutput (lib/strider/control/
// hal_interfaces.h). Writes go to a shadow of every channel; flush() sends
// only the channels that changed since the last frame, consecutive ones in
// one auto-increment burst (up to 8 per transfer), so a frame of 18 servos
// costs a few transfers instead of 18 (and the PRESCALE register is never
// re-read: the timing is cached in lib/strider/control/pca9685_timing.h).
//
// Faults: a board whose transfer fails (no ACK: missing, unpowered, a loose
// wire; or a time-out: the bus held low), or whose MODE1 or prescale is no
// longer what the firmware set (it lost its supply for a moment and reset;
// read every kCheckMs, also while no frame goes to it), is taken as faulted
// and gets no more frames; service() probes it every kProbeMs and, once it answers,
// sets it up again if it lost its registers (asleep or at another
// prescale: prescale, mode, every output off) or reads back what it
// drives if it kept them. report() tells RobotApp (control/servo_boards.h),
// which switches that board's legs on again from what they drive.
#ifndef STRIDER_PCA9685_OUTPUT_H
#define STRIDER_PCA9685_OUTPUT_H

#include <stdint.h>

#include "control/channel_map.h"
#include "control/servo_boards.h"

class Pca9685Output {
 public:
  static constexpr uint8_t kMaxChannels = strider::kMaxPcaBoards * strider::kPcaChannelsPerBoard;
  static constexpr uint16_t kFullOff = strider::kPcaFullOff;
  static constexpr uint16_t kProbeMs = 100;  //!< a faulted board is probed this often [ms]
  static constexpr uint16_t kCheckMs = 250;  //!< a working board's MODE1 and prescale are read this often [ms]

  //! The shadow is the caller's: `channels` entries (at most kMaxChannels),
  //! 16 per board its model uses, so that a one-board robot keeps no shadow
  //! of a second board. Writes to other channels are ignored.
  Pca9685Output(uint16_t* shadow, uint8_t channels)
      : off_(shadow), channels_(channels <= kMaxChannels ? channels : kMaxChannels) {}

  //! Starts the bus and `boards` boards. warm_prescale 0: every board is put
  //! to sleep with every output off (a power-up). Otherwise (an MCU reset) a
  //! board found awake, as this firmware runs it, at warm_prescale keeps
  //! its outputs: they are read back into the shadow (held()); the others
  //! are put to sleep with every output off. A board that does not answer
  //! is faulted (report()).
  void begin(uint8_t boards, uint8_t warm_prescale);
  //! Outputs that kept a pulse through the reset (begin()).
  uint8_t held() const { return held_; }
  //! What every channel drives (OFF words, kFullOff: no pulse), channels() entries.
  const uint16_t* outputs() const { return off_; }
  uint8_t channels() const { return channels_; }

  void write_ticks(uint8_t channel, uint16_t off_ticks) { set(channel, uint16_t(off_ticks & 0x0FFF)); }
  void relax(uint8_t channel) { set(channel, kFullOff); }
  //! Every board not yet at `prescale` (asleep, write, wake, restart).
  void set_prescale(uint8_t prescale);
  //! Sends the changed channels to the boards that answer.
  void flush();

  //! Checks the working boards (every kCheckMs), probes the faulted ones
  //! (every kProbeMs) and takes back one that answers. Call once per tick,
  //! before the frame.
  void service(uint32_t now_ms);
  //! The boards' state for RobotApp::servo_boards(); clears `restored`.
  strider::ServoBoardReport report();

  uint16_t bytes_last_frame() const { return bytes_; }  //!< I2C payload bytes of the last flush
  uint16_t bus_errors() const { return errors_; }       //!< transfers that failed (not probes)

 private:
  void set(uint8_t channel, uint16_t off) {
    if (channel >= channels_ || off_[channel] == off) return;
    off_[channel] = off;
    dirty_ |= uint32_t(1) << channel;
  }
  uint8_t all_boards() const { return uint8_t((1u << boards_) - 1u); }
  //! A transfer to board b failed: b (every board, when the bus timed out) is faulted.
  void fail(uint8_t b);
  //! Whether the working boards still run as set (MODE1, prescale); faults the others.
  void check();
  //! Probes the faulted boards and takes back the ones that answer.
  void probe();
  //! Board b answers again: set up anew or read back; false if that failed.
  bool take_back(uint8_t b);
  //! Reads board b's outputs into the shadow (they are what it drives).
  bool read_back(uint8_t b);

  uint16_t* off_;
  uint8_t channels_;
  uint32_t dirty_ = 0;
  uint16_t bytes_ = 0;
  uint16_t errors_ = 0;
  uint8_t boards_ = 0;
  uint8_t held_ = 0;
  uint8_t faulted_ = 0;   // boards that do not answer
  uint8_t restored_ = 0;  // boards that answer again, since the last report()
  bool bus_stuck_ = false;
  uint8_t prescale_ = 0;  // what every board should run at (0: not yet set)
  uint8_t running_[strider::kMaxPcaBoards] = {};  // the prescale board b runs at (0: asleep, unknown)
  uint32_t next_probe_ms_ = 0;
  uint32_t next_check_ms_ = 0;
};

#endif
