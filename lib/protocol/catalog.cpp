#include "protocol/catalog.hpp"

#include <array>

#include "protocol/codec_instances.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace {

template <WireStruct T>
const PayloadCodec* c() {
  return &codec_of<T>();
}

RequestKind query(std::string_view name, std::uint16_t subtype, const PayloadCodec* reply,
                  std::string_view summary) {
  return {name, subtype, RequestForm::kQuery, nullptr, reply, summary};
}

RequestKind set(std::string_view name, std::uint16_t subtype, const PayloadCodec* request,
                const PayloadCodec* reply, std::string_view summary) {
  return {name, subtype, RequestForm::kStruct, request, reply, summary};
}

// Built on first use, so that the codec singletons exist before the tables do.
struct Catalog {
  std::vector<RequestKind> player, power, position, position3d, sonar, laser, blobfinder, ptz,
      audiodsp, audiomixer, fiducial, bumper, truth, idar, idarturret, wifi, ir, localize, mcom;
  std::vector<InterfaceMessages> interfaces;

  Catalog() {
    player = {
        query("devlist", kPlayerDevlistReq, c<DeviceList>(), "list the devices on this port"),
        set("driverinfo", kPlayerDriverinfoReq, c<DriverInfo>(), c<DriverInfo>(),
            "name of the driver behind a device id"),
        set("dev", kPlayerDevReq, c<DeviceAccessRequest>(), c<DeviceAccessReply>(),
            "open, change or close access to a device"),
        set("data", kPlayerDataReq, c<DataRequest>(), nullptr, "ask for one round of data (pull modes)"),
        set("datamode", kPlayerDatamodeReq, c<DataModeRequest>(), nullptr, "change the data delivery mode"),
        set("datafreq", kPlayerDatafreqReq, c<DataFrequencyRequest>(), nullptr, "change the push frequency (Hz)"),
        set("auth", kPlayerAuthReq, c<AuthRequest>(), nullptr, "present the authentication key"),
        set("nameservice", kPlayerNameserviceReq, c<NameServiceRequest>(), c<NameServiceRequest>(),
            "look up a robot name and get its port"),
    };
    power = {query("main-power", kMainPowerReq, c<PowerData>(), "read the battery voltage")};
    position = {
        query("get-geom", kPositionGetGeomReq, c<PositionGeom>(), "base pose and footprint"),
        set("motor-power", kPositionMotorPowerReq, c<PositionPowerConfig>(), nullptr, "motors on (value=1) or off"),
        set("velocity-mode", kPositionVelocityModeReq, c<PositionVelocityModeConfig>(), nullptr,
            "select the velocity control scheme"),
        set("reset-odom", kPositionResetOdomReq, c<PositionResetOdomConfig>(), nullptr, "zero the odometry"),
        set("position-mode", kPositionPositionModeReq, c<PositionPositionModeRequest>(), nullptr,
            "velocity (state=0) or position (state=1) control"),
        set("speed-pid", kPositionSpeedPidReq, c<PositionSpeedPidRequest>(), nullptr, "speed PID gains"),
        set("position-pid", kPositionPositionPidReq, c<PositionPositionPidRequest>(), nullptr,
            "position PID gains"),
        set("speed-prof", kPositionSpeedProfReq, c<PositionSpeedProfRequest>(), nullptr,
            "maximum speed and acceleration"),
        set("set-odom", kPositionSetOdomReq, c<PositionSetOdomRequest>(), nullptr, "set the odometric pose"),
        set("rmp-velocity-scale", kPositionRmpVelocityScale, c<RmpConfig>(), nullptr, "Segway RMP velocity scale"),
        set("rmp-accel-scale", kPositionRmpAccelScale, c<RmpConfig>(), nullptr, "Segway RMP acceleration scale"),
        set("rmp-turn-scale", kPositionRmpTurnScale, c<RmpConfig>(), nullptr, "Segway RMP turn scale"),
        set("rmp-gain-schedule", kPositionRmpGainSchedule, c<RmpConfig>(), nullptr, "Segway RMP gain schedule"),
        set("rmp-current-limit", kPositionRmpCurrentLimit, c<RmpConfig>(), nullptr, "Segway RMP current limit"),
        set("rmp-rst-integrators", kPositionRmpRstIntegrators, c<RmpConfig>(), nullptr,
            "Segway RMP: reset integrators (value = bit mask)"),
        set("rmp-shutdown", kPositionRmpShutdown, c<RmpConfig>(), nullptr, "Segway RMP: shut down"),
    };
    // player.h has no position3d geometry struct; the 3-D drivers answer with the
    // 2-D one, whose layout the request kind reuses.
    position3d = {
        query("get-geom", kPosition3dGetGeomReq, c<PositionGeom>(), "base pose and footprint"),
        set("motor-power", kPosition3dMotorPowerReq, c<Position3dPowerConfig>(), nullptr, "motors on or off"),
        set("velocity-mode", kPosition3dVelocityModeReq, c<PositionVelocityModeConfig>(), nullptr,
            "select the velocity control scheme"),
        set("position-mode", kPosition3dPositionModeReq, c<PositionPositionModeRequest>(), nullptr,
            "velocity or position control"),
    };
    sonar = {
        query("get-geom", kSonarGetGeomReq, c<SonarGeom>(), "transducer poses"),
        set("power", kSonarPowerReq, c<SonarPowerConfig>(), nullptr, "sonar on (value=1) or off"),
    };
    laser = {
        query("get-geom", kLaserGetGeom, c<LaserGeom>(), "laser pose and size"),
        set("set-config", kLaserSetConfig, c<LaserConfig>(), c<LaserConfig>(), "set scan angles and resolution"),
        query("get-config", kLaserGetConfig, c<LaserConfig>(), "read scan angles and resolution"),
        set("power", kLaserPowerConfig, c<LaserPowerConfig>(), nullptr, "laser on (value=1) or off"),
    };
    blobfinder = {
        set("set-color", kBlobfinderSetColorReq, c<BlobfinderColorConfig>(), nullptr, "colour range to track"),
        set("set-imager-params", kBlobfinderSetImagerParamsReq, c<BlobfinderImagerConfig>(), nullptr,
            "camera brightness, contrast, colour mode, gain"),
    };
    ptz = {
        set("generic", kPtzGenericConfigReq, c<PtzGenericConfig>(), c<PtzGenericConfig>(),
            "raw unit-specific command"),
        set("control-mode", kPtzControlModeReq, c<PtzVelocityModeConfig>(), nullptr,
            "velocity (mode=0) or position (mode=1) control"),
    };
    audiodsp = {
        set("set-config", kAudiodspSetConfig, c<AudioDspConfig>(), c<AudioDspConfig>(), "sample format, rate, channels"),
        query("get-config", kAudiodspGetConfig, c<AudioDspConfig>(), "read the sampling configuration"),
    };
    // The 1.5 mixer driver answers any one-byte request with the levels.
    audiomixer = {query("get-levels", 0, c<AudioMixerConfig>(), "read the mixer levels")};
    fiducial = {
        query("get-geom", kFiducialGetGeom, c<FiducialGeom>(), "detector pose and size"),
        query("get-fov", kFiducialGetFov, c<FiducialFov>(), "read the field of view"),
        set("set-fov", kFiducialSetFov, c<FiducialFov>(), c<FiducialFov>(), "set the field of view"),
        set("send-msg", kFiducialSendMsg, c<FiducialMsgTxRequest>(), nullptr, "send a message to a fiducial"),
        set("recv-msg", kFiducialRecvMsg, c<FiducialMsgRxRequest>(), c<FiducialMsg>(), "read the last message"),
        set("exchange-msg", kFiducialExchangeMsg, c<FiducialMsgTxRxRequest>(), c<FiducialMsg>(),
            "send, then read the last message"),
    };
    bumper = {query("get-geom", kBumperGetGeomReq, c<BumperGeom>(), "bumper geometry")};
    truth = {
        query("get-pose", kTruthGetPose, c<TruthPose>(), "read the pose"),
        set("set-pose", kTruthSetPose, c<TruthPose>(), nullptr, "set the pose"),
        set("set-pose-on-root", kTruthSetPoseOnRoot, c<TruthPose>(), nullptr, "set the pose on the background"),
        query("get-fiducial-id", kTruthGetFiducialId, c<TruthFiducialId>(), "read the fiducial id"),
        set("set-fiducial-id", kTruthSetFiducialId, c<TruthFiducialId>(), nullptr, "set the fiducial id"),
    };
    idar = {
        set("transmit", kIdarTransmit, c<IdarConfig>(), nullptr, "transmit a message"),
        set("receive", kIdarReceive, c<IdarConfig>(), c<IdarRx>(), "receive and flush"),
        set("receive-noflush", kIdarReceiveNoflush, c<IdarConfig>(), c<IdarRx>(), "receive, keep"),
        set("transmit-receive", kIdarTransmitReceive, c<IdarConfig>(), c<IdarRx>(), "transmit, then receive"),
    };
    idarturret = {
        set("transmit", kIdarTransmit, c<IdarTurretConfig>(), nullptr, "transmit on every IDAR"),
        set("receive", kIdarReceive, c<IdarTurretConfig>(), c<IdarTurretReply>(), "receive and flush"),
        set("receive-noflush", kIdarReceiveNoflush, c<IdarTurretConfig>(), c<IdarTurretReply>(), "receive, keep"),
        set("transmit-receive", kIdarTransmitReceive, c<IdarTurretConfig>(), c<IdarTurretReply>(),
            "transmit, then receive"),
    };
    wifi = {
        query("mac", kWifiMacReq, nullptr, "MAC address of the interface"),
        set("iwspy-add", kWifiIwspyAddReq, c<WifiIwspyAddrRequest>(), nullptr, "add an iwspy address"),
        set("iwspy-del", kWifiIwspyDelReq, c<WifiIwspyAddrRequest>(), nullptr, "remove an iwspy address"),
        set("iwspy-ping", kWifiIwspyPingReq, c<WifiIwspyAddrRequest>(), nullptr, "ping the iwspy addresses"),
    };
    ir = {
        query("pose", kIrPoseReq, c<IrPoseRequest>(), "sensor poses"),
        set("power", kIrPowerReq, c<IrPowerRequest>(), nullptr, "IR on (state=1) or off"),
    };
    localize = {
        set("set-pose", kLocalizeSetPoseReq, c<LocalizeSetPose>(), nullptr, "set the pose estimate"),
        query("get-config", kLocalizeGetConfigReq, c<LocalizeConfig>(), "read the filter configuration"),
        set("set-config", kLocalizeSetConfigReq, c<LocalizeConfig>(), nullptr, "set the particle count"),
        query("get-map-info", kLocalizeGetMapInfoReq, c<LocalizeMapInfo>(), "map size and scale"),
        set("get-map-data", kLocalizeGetMapDataReq, c<LocalizeMapData>(), c<LocalizeMapData>(),
            "one map tile (col, row, width, height)"),
    };
    mcom = {
        set("push", kMcomPushReq, c<McomConfig>(), nullptr, "push a message onto a channel"),
        set("pop", kMcomPopReq, c<McomConfig>(), c<McomReturn>(), "pop the newest message"),
        set("read", kMcomReadReq, c<McomConfig>(), c<McomReturn>(), "read the newest message, keep it"),
        set("clear", kMcomClearReq, c<McomConfig>(), nullptr, "clear a channel"),
        set("set-capacity", kMcomSetCapacityReq, c<McomConfig>(), nullptr, "set a channel's capacity"),
    };

    auto add = [&](std::uint16_t code, const PayloadCodec* data, const PayloadCodec* command,
                   const std::vector<RequestKind>* requests) {
      InterfaceMessages m;
      m.interface = code;
      m.subtype_size = code == kPlayerCode ? 2 : 1;
      m.data = data;
      m.command = command;
      if (requests) m.requests = *requests;
      interfaces.push_back(m);
    };
    add(kPlayerCode, nullptr, nullptr, &player);
    add(kPowerCode, c<PowerData>(), nullptr, &power);
    add(kGripperCode, c<GripperData>(), c<GripperCommand>(), nullptr);
    add(kPositionCode, c<PositionData>(), c<PositionCommand>(), &position);
    add(kSonarCode, c<SonarData>(), nullptr, &sonar);
    add(kLaserCode, c<LaserData>(), nullptr, &laser);
    add(kBlobfinderCode, c<BlobfinderData>(), nullptr, &blobfinder);
    add(kPtzCode, c<PtzData>(), c<PtzCommand>(), &ptz);
    add(kAudioCode, c<AudioData>(), c<AudioCommand>(), nullptr);
    add(kFiducialCode, c<FiducialData>(), nullptr, &fiducial);
    add(kCommsCode, c<CommsData>(), c<CommsCommand>(), nullptr);
    add(kSpeechCode, nullptr, c<SpeechCommand>(), nullptr);
    add(kGpsCode, c<GpsData>(), nullptr, nullptr);
    add(kBumperCode, c<BumperData>(), nullptr, &bumper);
    add(kTruthCode, c<TruthData>(), nullptr, &truth);
    add(kIdarturretCode, nullptr, nullptr, &idarturret);
    add(kIdarCode, nullptr, nullptr, &idar);
    // The descartes "config" struct is what its driver takes as a command.
    add(kDescartesCode, c<DescartesData>(), c<DescartesConfig>(), nullptr);
    add(kDioCode, c<DioData>(), nullptr, nullptr);
    add(kAioCode, c<AioData>(), nullptr, nullptr);
    add(kIrCode, c<IrData>(), nullptr, &ir);
    add(kWifiCode, c<WifiData>(), nullptr, &wifi);
    add(kWaveformCode, c<WaveformData>(), nullptr, nullptr);
    add(kLocalizeCode, c<LocalizeData>(), nullptr, &localize);
    add(kMcomCode, nullptr, nullptr, &mcom);
    add(kSoundCode, nullptr, c<SoundCommand>(), nullptr);
    add(kAudiodspCode, c<AudioDspData>(), c<AudioDspCommand>(), &audiodsp);
    add(kAudiomixerCode, nullptr, c<AudioMixerCommand>(), &audiomixer);
    add(kPosition3dCode, c<Position3dData>(), c<Position3dCommand>(), &position3d);
    add(kSimulationCode, c<SimulationData>(), c<SimulationCommand>(), nullptr);
    add(kServiceAdvCode, nullptr, nullptr, nullptr);
    add(kBlinkenlightCode, c<BlinkenlightData>(), c<BlinkenlightData>(), nullptr);
    add(kNomadCode, c<NomadData>(), c<NomadCommand>(), nullptr);
    add(kCameraCode, c<CameraData>(), nullptr, nullptr);
    add(kNullCode, nullptr, nullptr, nullptr);
  }
};

const Catalog& catalog() {
  static const Catalog instance;
  return instance;
}

}  // namespace

const RequestKind* InterfaceMessages::find_request(std::string_view name) const {
  for (const auto& kind : requests) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

const RequestKind* InterfaceMessages::find_request(std::uint16_t subtype) const {
  for (const auto& kind : requests) {
    if (kind.subtype == subtype) return &kind;
  }
  return nullptr;
}

const InterfaceMessages* find_messages(std::uint16_t interface) {
  for (const auto& m : catalog().interfaces) {
    if (m.interface == interface) return &m;
  }
  return nullptr;
}

std::span<const InterfaceMessages> all_messages() { return catalog().interfaces; }

}  // namespace playerkit::protocol
