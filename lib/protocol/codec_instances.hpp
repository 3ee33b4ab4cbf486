#pragma once
// The codecs of every wire struct (encode, decode, to_json, from_json) are
// compiled once, in the codec_instances_*.cpp files of the library, instead of
// in every file that uses them: they are the most expensive templates of the
// project to instantiate. A file that includes this header uses those copies;
// one that does not still compiles its own, only slower.

#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/binary_codec.hpp"
#include "protocol/json_codec.hpp"
#include "protocol/messages/all.hpp"

// Every wire struct of messages/all.hpp, in four groups (one .cpp each, so
// two cores compile them side by side).
#define PLAYERKIT_WIRE_STRUCTS_A(X) \
  X(MessageHeader) \
  X(DeviceId) \
  X(DeviceList) \
  X(DriverInfo) \
  X(DeviceAccessRequest) \
  X(DeviceAccessReply) \
  X(DataRequest) \
  X(DataModeRequest) \
  X(DataFrequencyRequest) \
  X(AuthRequest) \
  X(NameServiceRequest) \
  X(PowerData) \
  X(PowerConfig) \
  X(GripperData) \
  X(GripperCommand) \
  X(PositionData) \
  X(PositionCommand) \
  X(PositionGeom) \
  X(PositionPowerConfig) \
  X(PositionVelocityModeConfig) \
  X(PositionResetOdomConfig) \
  X(PositionPositionModeRequest) \
  X(PositionSetOdomRequest) \
  X(PositionSpeedPidRequest) \
  X(PositionPositionPidRequest) \
  X(PositionSpeedProfRequest) \
  X(RmpConfig) \
  X(Position3dData)

#define PLAYERKIT_WIRE_STRUCTS_B(X) \
  X(Position3dCommand) \
  X(Position3dPowerConfig) \
  X(SonarData) \
  X(SonarGeom) \
  X(SonarPowerConfig) \
  X(LaserData) \
  X(LaserGeom) \
  X(LaserConfig) \
  X(LaserPowerConfig) \
  X(BlobfinderChannel) \
  X(BlobfinderBlob) \
  X(BlobfinderData) \
  X(BlobfinderColorConfig) \
  X(BlobfinderImagerConfig) \
  X(PtzData) \
  X(PtzCommand) \
  X(PtzGenericConfig) \
  X(PtzVelocityModeConfig) \
  X(CameraData) \
  X(AudioData) \
  X(AudioCommand) \
  X(AudioDspData) \
  X(AudioDspCommand) \
  X(AudioDspConfig) \
  X(AudioMixerConfig) \
  X(AudioMixerCommand) \
  X(WaveformData) \
  X(BlinkenlightData)

#define PLAYERKIT_WIRE_STRUCTS_C(X) \
  X(FiducialItem) \
  X(FiducialData) \
  X(FiducialGeom) \
  X(FiducialFov) \
  X(FiducialMsg) \
  X(FiducialMsgRxRequest) \
  X(FiducialMsgTxRequest) \
  X(FiducialMsgTxRxRequest) \
  X(CommsData) \
  X(CommsCommand) \
  X(SpeechCommand) \
  X(GpsData) \
  X(BumperData) \
  X(BumperDefine) \
  X(BumperGeom) \
  X(TruthData) \
  X(TruthPose) \
  X(TruthFiducialId) \
  X(SimulationData) \
  X(SimulationCommand) \
  X(IdarTx) \
  X(IdarRx) \
  X(IdarConfig) \
  X(IdarTurretReply) \
  X(IdarTurretConfig) \
  X(DescartesConfig) \
  X(DescartesData) \
  X(RflexConfig)

#define PLAYERKIT_WIRE_STRUCTS_D(X) \
  X(DioData) \
  X(AioData) \
  X(BpsData) \
  X(BpsConfig) \
  X(BpsBeacon) \
  X(JoystickData) \
  X(RwiConfig) \
  X(WifiMacRequest) \
  X(WifiIwspyAddrRequest) \
  X(WifiLink) \
  X(WifiData) \
  X(IrData) \
  X(IrPose) \
  X(IrPoseRequest) \
  X(IrPowerRequest) \
  X(LocalizeHypothesis) \
  X(LocalizeData) \
  X(LocalizeSetPose) \
  X(LocalizeConfig) \
  X(LocalizeMapInfo) \
  X(LocalizeMapData) \
  X(McomData) \
  X(McomConfig) \
  X(McomReturn) \
  X(NomadData) \
  X(NomadCommand) \
  X(SoundCommand)

#define PLAYERKIT_WIRE_STRUCTS(X) \
  PLAYERKIT_WIRE_STRUCTS_A(X) PLAYERKIT_WIRE_STRUCTS_B(X) PLAYERKIT_WIRE_STRUCTS_C(X) PLAYERKIT_WIRE_STRUCTS_D(X)

#define PLAYERKIT_CODEC_INSTANCES(prefix, T)                                      \
  prefix template std::vector<std::uint8_t> encode<T>(const T&);                  \
  prefix template T decode<T>(std::span<const std::uint8_t>);                     \
  prefix template nlohmann::json to_json<T>(const T&);                            \
  prefix template T from_json<T>(const nlohmann::json&);

namespace playerkit::protocol {

#define PLAYERKIT_EXTERN_CODECS(T) PLAYERKIT_CODEC_INSTANCES(extern, T)
PLAYERKIT_WIRE_STRUCTS(PLAYERKIT_EXTERN_CODECS)
#undef PLAYERKIT_EXTERN_CODECS

namespace detail {
#define PLAYERKIT_COUNT_ONE(T) +1
inline constexpr std::size_t kInstantiatedWireStructs = 0 PLAYERKIT_WIRE_STRUCTS(PLAYERKIT_COUNT_ONE);
#undef PLAYERKIT_COUNT_ONE
}  // namespace detail
static_assert(detail::kInstantiatedWireStructs == AllWireStructs::size,
              "a wire struct was added to messages/all.hpp but not to PLAYERKIT_WIRE_STRUCTS");

}  // namespace playerkit::protocol
