#include "protocol/interfaces.hpp"

#include <array>
#include <string>

namespace playerkit::protocol {
namespace {

// The default-driver column is deviceregistry.cc's table; where `laser` appears
// twice there, lookup takes the first entry (sicklms200).
constexpr std::array<InterfaceInfo, 35> kInterfaces{{
    {kPlayerCode, "player", "PLAYER_PLAYER_CODE", ""},
    {kPowerCode, "power", "PLAYER_POWER_CODE", "p2os_power"},
    {kGripperCode, "gripper", "PLAYER_GRIPPER_CODE", "p2os_gripper"},
    {kPositionCode, "position", "PLAYER_POSITION_CODE", "p2os_position"},
    {kSonarCode, "sonar", "PLAYER_SONAR_CODE", "p2os_sonar"},
    {kLaserCode, "laser", "PLAYER_LASER_CODE", "sicklms200"},
    {kBlobfinderCode, "blobfinder", "PLAYER_BLOBFINDER_CODE", "acts"},
    {kPtzCode, "ptz", "PLAYER_PTZ_CODE", "sonyevid30"},
    {kAudioCode, "audio", "PLAYER_AUDIO_CODE", "fixedtones"},
    {kFiducialCode, "fiducial", "PLAYER_FIDUCIAL_CODE", "laserbarcode"},
    {kCommsCode, "comms", "PLAYER_COMMS_CODE", "udpbroadcast"},
    {kSpeechCode, "speech", "PLAYER_SPEECH_CODE", "festival"},
    {kGpsCode, "gps", "PLAYER_GPS_CODE", "garminnmea"},
    {kBumperCode, "bumper", "PLAYER_BUMPER_CODE", "p2os_bumper"},
    {kTruthCode, "truth", "PLAYER_TRUTH_CODE", "passthrough"},
    {kIdarturretCode, "idarturret", "PLAYER_IDARTURRET_CODE", ""},
    {kIdarCode, "idar", "PLAYER_IDAR_CODE", ""},
    {kDescartesCode, "descartes", "PLAYER_DESCARTES_CODE", ""},
    {kDioCode, "dio", "PLAYER_DIO_CODE", "p2os_dio"},
    {kAioCode, "aio", "PLAYER_AIO_CODE", "p2os_aio"},
    {kIrCode, "ir", "PLAYER_IR_CODE", "reb_ir"},
    {kWifiCode, "wifi", "PLAYER_WIFI_CODE", "linuxwifi"},
    {kWaveformCode, "waveform", "PLAYER_WAVEFORM_CODE", "wave_audio"},
    {kLocalizeCode, "localize", "PLAYER_LOCALIZE_CODE", "amcl"},
    {kMcomCode, "mcom", "PLAYER_MCOM_CODE", "lifomcom"},
    {kSoundCode, "sound", "PLAYER_SOUND_CODE", "p2os_sound"},
    {kAudiodspCode, "audiodsp", "PLAYER_AUDIODSP_CODE", "acoustics"},
    {kAudiomixerCode, "audiomixer", "PLAYER_AUDIOMIXER_CODE", "mixer"},
    {kPosition3dCode, "position3d", "PLAYER_POSITION3D_CODE", "segwayrmp"},
    {kSimulationCode, "simulation", "PLAYER_SIMULATION_CODE", "stg_simulation"},
    {kServiceAdvCode, "service_adv", "PLAYER_SERVICE_ADV_CODE", "service_adv_lsd"},
    {kBlinkenlightCode, "blinkenlight", "PLAYER_BLINKENLIGHT_CODE", "stg_blinkenlight"},
    {kNomadCode, "nomad", "PLAYER_NOMAD_CODE", "nomad"},
    {kCameraCode, "camera", "PLAYER_CAMERA_CODE", "camerav4l"},
    {kNullCode, "null", "PLAYER_NULL_CODE", "writelog"},
}};

}  // namespace

std::span<const InterfaceInfo> all_interfaces() { return kInterfaces; }

const InterfaceInfo* find_interface(std::string_view name) {
  for (const auto& info : kInterfaces) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

const InterfaceInfo* find_interface(std::uint16_t code) {
  for (const auto& info : kInterfaces) {
    if (info.code == code) return &info;
  }
  return nullptr;
}

std::string interface_name(std::uint16_t code) {
  if (const auto* info = find_interface(code)) return std::string(info->name);
  return "interface " + std::to_string(code);
}

}  // namespace playerkit::protocol
