#pragma once
// Every Player 1.5 wire struct, and a type list of all 111 of them for code that
// must treat each one (layout checks, tests, the catalog).

#include "protocol/messages/header.hpp"
#include "protocol/messages/player.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/gripper.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/ptz.hpp"
#include "protocol/messages/camera.hpp"
#include "protocol/messages/audio.hpp"
#include "protocol/messages/audiodsp.hpp"
#include "protocol/messages/audiomixer.hpp"
#include "protocol/messages/waveform.hpp"
#include "protocol/messages/blinkenlight.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/comms.hpp"
#include "protocol/messages/speech.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/truth.hpp"
#include "protocol/messages/simulation.hpp"
#include "protocol/messages/idar.hpp"
#include "protocol/messages/idarturret.hpp"
#include "protocol/messages/descartes.hpp"
#include "protocol/messages/rflex.hpp"
#include "protocol/messages/dio.hpp"
#include "protocol/messages/aio.hpp"
#include "protocol/messages/bps.hpp"
#include "protocol/messages/joystick.hpp"
#include "protocol/messages/rwi.hpp"
#include "protocol/messages/wifi.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/localize.hpp"
#include "protocol/messages/mcom.hpp"
#include "protocol/messages/nomad.hpp"
#include "protocol/messages/sound.hpp"

namespace playerkit::protocol {

template <class... T>
struct TypeList {
  static constexpr std::size_t size = sizeof...(T);
};

using AllWireStructs = TypeList<
    MessageHeader,
    DeviceId,
    DeviceList,
    DriverInfo,
    DeviceAccessRequest,
    DeviceAccessReply,
    DataRequest,
    DataModeRequest,
    DataFrequencyRequest,
    AuthRequest,
    NameServiceRequest,
    PowerData,
    PowerConfig,
    GripperData,
    GripperCommand,
    PositionData,
    PositionCommand,
    PositionGeom,
    PositionPowerConfig,
    PositionVelocityModeConfig,
    PositionResetOdomConfig,
    PositionPositionModeRequest,
    PositionSetOdomRequest,
    PositionSpeedPidRequest,
    PositionPositionPidRequest,
    PositionSpeedProfRequest,
    RmpConfig,
    Position3dData,
    Position3dCommand,
    Position3dPowerConfig,
    SonarData,
    SonarGeom,
    SonarPowerConfig,
    LaserData,
    LaserGeom,
    LaserConfig,
    LaserPowerConfig,
    BlobfinderChannel,
    BlobfinderBlob,
    BlobfinderData,
    BlobfinderColorConfig,
    BlobfinderImagerConfig,
    PtzData,
    PtzCommand,
    PtzGenericConfig,
    PtzVelocityModeConfig,
    CameraData,
    AudioData,
    AudioCommand,
    AudioDspData,
    AudioDspCommand,
    AudioDspConfig,
    AudioMixerConfig,
    AudioMixerCommand,
    WaveformData,
    BlinkenlightData,
    FiducialItem,
    FiducialData,
    FiducialGeom,
    FiducialFov,
    FiducialMsg,
    FiducialMsgRxRequest,
    FiducialMsgTxRequest,
    FiducialMsgTxRxRequest,
    CommsData,
    CommsCommand,
    SpeechCommand,
    GpsData,
    BumperData,
    BumperDefine,
    BumperGeom,
    TruthData,
    TruthPose,
    TruthFiducialId,
    SimulationData,
    SimulationCommand,
    IdarTx,
    IdarRx,
    IdarConfig,
    IdarTurretReply,
    IdarTurretConfig,
    DescartesConfig,
    DescartesData,
    RflexConfig,
    DioData,
    AioData,
    BpsData,
    BpsConfig,
    BpsBeacon,
    JoystickData,
    RwiConfig,
    WifiMacRequest,
    WifiIwspyAddrRequest,
    WifiLink,
    WifiData,
    IrData,
    IrPose,
    IrPoseRequest,
    IrPowerRequest,
    LocalizeHypothesis,
    LocalizeData,
    LocalizeSetPose,
    LocalizeConfig,
    LocalizeMapInfo,
    LocalizeMapData,
    McomData,
    McomConfig,
    McomReturn,
    NomadData,
    NomadCommand,
    SoundCommand>;

static_assert(AllWireStructs::size == 111);

}  // namespace playerkit::protocol
