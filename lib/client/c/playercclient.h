/*
 * The C client interface of Player 1.5 (manual, appendix A), on playerkit's
 * client library. Programs written against 1.5's playercclient.h compile
 * against this header unchanged: same function names and signatures, same
 * constant and type names and values (wire-format.md), same conventions:
 * functions return 0 when all went well and -1 otherwise, and never write
 * past a buffer length they are given.
 *
 * Byte order, as in 1.5: player_read() and player_request() hand back the
 * header in host order and the payload exactly as it came off the wire
 * (network order); player_write() and player_request() take the payload in
 * network order (htons/htonl it yourself) and build the header themselves.
 *
 * Plain C89; usable from C++. Not thread safe: one connection, one thread.
 */
#ifndef PLAYERKIT_PLAYERCCLIENT_H
#define PLAYERKIT_PLAYERCCLIENT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- protocol-wide constants ---------------------------------------- */

#define PLAYER_STXX 0x5878 /* header start marker: bytes 'X' 'x' */

#define PLAYER_MSGTYPE_DATA 1      /* sensor data, server to client */
#define PLAYER_MSGTYPE_CMD 2       /* command, client to server, never answered */
#define PLAYER_MSGTYPE_REQ 3       /* configuration request */
#define PLAYER_MSGTYPE_RESP_ACK 4  /* positive reply */
#define PLAYER_MSGTYPE_SYNCH 5     /* zero-length end of a data round */
#define PLAYER_MSGTYPE_RESP_NACK 6 /* request understood but refused */
#define PLAYER_MSGTYPE_RESP_ERR 7  /* no permission, unknown device, full queue */

#define PLAYER_MAX_DEVICE_STRING_LEN 64
#define PLAYER_MAX_DEVICES 64
/* The default 1.5 build, which every installed player.h gave its clients. */
#define PLAYER_MAX_MESSAGE_SIZE 8192
#define PLAYER_MAX_PAYLOAD_SIZE (PLAYER_MAX_MESSAGE_SIZE - 32)
#define PLAYER_MAX_REQREP_SIZE 4096
#define PLAYER_PORTNUM 6665
#define PLAYER_IDENT_STRLEN 32
#define PLAYER_IDENT_STRING "Player v."
#define PLAYER_KEYLEN 32

/* ---- interface codes and the names config files use ------------------ */

#define PLAYER_PLAYER_CODE 1
#define PLAYER_POWER_CODE 2
#define PLAYER_GRIPPER_CODE 3
#define PLAYER_POSITION_CODE 4
#define PLAYER_SONAR_CODE 5
#define PLAYER_LASER_CODE 6
#define PLAYER_BLOBFINDER_CODE 7
#define PLAYER_PTZ_CODE 8
#define PLAYER_AUDIO_CODE 9
#define PLAYER_FIDUCIAL_CODE 10
#define PLAYER_COMMS_CODE 11
#define PLAYER_SPEECH_CODE 12
#define PLAYER_GPS_CODE 13
#define PLAYER_BUMPER_CODE 14
#define PLAYER_TRUTH_CODE 15
#define PLAYER_IDARTURRET_CODE 16
#define PLAYER_IDAR_CODE 17
#define PLAYER_DESCARTES_CODE 18
#define PLAYER_DIO_CODE 20
#define PLAYER_AIO_CODE 21
#define PLAYER_IR_CODE 22
#define PLAYER_WIFI_CODE 23
#define PLAYER_WAVEFORM_CODE 24
#define PLAYER_LOCALIZE_CODE 25
#define PLAYER_MCOM_CODE 26
#define PLAYER_SOUND_CODE 27
#define PLAYER_AUDIODSP_CODE 28
#define PLAYER_AUDIOMIXER_CODE 29
#define PLAYER_POSITION3D_CODE 30
#define PLAYER_SIMULATION_CODE 31
#define PLAYER_SERVICE_ADV_CODE 32
#define PLAYER_BLINKENLIGHT_CODE 33
#define PLAYER_NOMAD_CODE 34
#define PLAYER_CAMERA_CODE 40
#define PLAYER_NULL_CODE 256

#define PLAYER_PLAYER_STRING "player"
#define PLAYER_POWER_STRING "power"
#define PLAYER_GRIPPER_STRING "gripper"
#define PLAYER_POSITION_STRING "position"
#define PLAYER_SONAR_STRING "sonar"
#define PLAYER_LASER_STRING "laser"
#define PLAYER_BLOBFINDER_STRING "blobfinder"
#define PLAYER_PTZ_STRING "ptz"
#define PLAYER_AUDIO_STRING "audio"
#define PLAYER_FIDUCIAL_STRING "fiducial"
#define PLAYER_COMMS_STRING "comms"
#define PLAYER_SPEECH_STRING "speech"
#define PLAYER_GPS_STRING "gps"
#define PLAYER_BUMPER_STRING "bumper"
#define PLAYER_TRUTH_STRING "truth"
#define PLAYER_IDARTURRET_STRING "idarturret"
#define PLAYER_IDAR_STRING "idar"
#define PLAYER_DESCARTES_STRING "descartes"
#define PLAYER_DIO_STRING "dio"
#define PLAYER_AIO_STRING "aio"
#define PLAYER_IR_STRING "ir"
#define PLAYER_WIFI_STRING "wifi"
#define PLAYER_WAVEFORM_STRING "waveform"
#define PLAYER_LOCALIZE_STRING "localize"
#define PLAYER_MCOM_STRING "mcom"
#define PLAYER_SOUND_STRING "sound"
#define PLAYER_AUDIODSP_STRING "audiodsp"
#define PLAYER_AUDIOMIXER_STRING "audiomixer"
#define PLAYER_POSITION3D_STRING "position3d"
#define PLAYER_SIMULATION_STRING "simulation"
#define PLAYER_SERVICE_ADV_STRING "service_adv"
#define PLAYER_BLINKENLIGHT_STRING "blinkenlight"
#define PLAYER_NOMAD_STRING "nomad"
#define PLAYER_CAMERA_STRING "camera"
#define PLAYER_NULL_STRING "null"

/* ---- the player device (code 1) -------------------------------------- */

/* Access letters of player_request_device_access(). */
#define PLAYER_READ_MODE 'r'
#define PLAYER_WRITE_MODE 'w'
#define PLAYER_ALL_MODE 'a'
#define PLAYER_CLOSE_MODE 'c'
#define PLAYER_ERROR_MODE 'e' /* only ever granted: the device could not be opened */

#define PLAYER_DATAMODE_PUSH_ALL 0
#define PLAYER_DATAMODE_PULL_ALL 1
#define PLAYER_DATAMODE_PUSH_NEW 2 /* the server's default */
#define PLAYER_DATAMODE_PULL_NEW 3

/* Request subtypes of the player device: uint16, network order, first. */
#define PLAYER_PLAYER_DEVLIST_REQ 1
#define PLAYER_PLAYER_DRIVERINFO_REQ 2
#define PLAYER_PLAYER_DEV_REQ 3
#define PLAYER_PLAYER_DATA_REQ 4
#define PLAYER_PLAYER_DATAMODE_REQ 5
#define PLAYER_PLAYER_DATAFREQ_REQ 6
#define PLAYER_PLAYER_AUTH_REQ 7
#define PLAYER_PLAYER_NAMESERVICE_REQ 8

/* ---- wire structs: packed, multi-byte fields in network order --------- */

#pragma pack(push, 1)

/* The 32-byte header of every message. */
typedef struct player_msghdr {
  uint16_t stx;
  uint16_t type;
  uint16_t device;
  uint16_t device_index;
  uint32_t time_sec;
  uint32_t time_usec;
  uint32_t timestamp_sec;
  uint32_t timestamp_usec;
  uint32_t reserved;
  uint32_t size; /* payload bytes after the header */
} player_msghdr_t;

typedef struct player_device_id {
  uint16_t code;
  uint16_t index;
  uint16_t port;
} player_device_id_t;

typedef struct player_device_devlist {
  uint16_t subtype;
  uint16_t device_count;
  player_device_id_t devices[PLAYER_MAX_DEVICES];
} player_device_devlist_t;

typedef struct player_device_driverinfo {
  uint16_t subtype;
  player_device_id_t id;
  char driver_name[PLAYER_MAX_DEVICE_STRING_LEN];
} player_device_driverinfo_t;

typedef struct player_device_req {
  uint16_t subtype;
  uint16_t code;
  uint16_t index;
  uint8_t access;
} player_device_req_t;

typedef struct player_device_resp {
  uint16_t subtype;
  uint16_t code;
  uint16_t index;
  uint8_t access; /* what was granted */
  uint8_t driver_name[PLAYER_MAX_DEVICE_STRING_LEN];
} player_device_resp_t;

typedef struct player_device_data_req {
  uint16_t subtype;
} player_device_data_req_t;

typedef struct player_device_datamode_req {
  uint16_t subtype;
  uint8_t mode;
} player_device_datamode_req_t;

typedef struct player_device_datafreq_req {
  uint16_t subtype;
  uint16_t frequency;
} player_device_datafreq_req_t;

typedef struct player_device_auth_req {
  uint16_t subtype;
  uint8_t auth_key[PLAYER_KEYLEN];
} player_device_auth_req_t;

typedef struct player_device_nameservice_req {
  uint16_t subtype;
  uint8_t name[PLAYER_MAX_DEVICE_STRING_LEN];
  uint16_t port;
} player_device_nameservice_req_t;

/* The command of the appendix's player_write() example (1.5 layout). */
typedef struct player_position_cmd {
  int32_t xpos, ypos, yaw;             /* mm, mm, degrees (position mode) */
  int32_t xspeed, yspeed, yawspeed;    /* mm/s, mm/s, deg/s */
  uint8_t state;                       /* motor enable */
  uint8_t type;                        /* 0 velocity, 1 position command */
} player_position_cmd_t;

#pragma pack(pop)

/* ---- the connection -------------------------------------------------- */

struct player_connection_impl; /* playerkit's client, opaque to C */

typedef struct player_connection {
  int sock; /* the socket, for select()/poll(); -1 when not connected */
  char banner[PLAYER_IDENT_STRLEN]; /* "Player v.1.5", NUL padded */
  struct player_connection_impl* impl; /* NULL when not connected */
} player_connection_t;

/* ---- the functions of appendix A ------------------------------------- */

#define PLAYER_CCLIENT_DEBUG_LEVEL_DEFAULT 5

/*
 * How much the functions below print on stderr when something goes wrong:
 * 0 nothing, 1 errors (a -1 return), 2 and up warnings too (truncated
 * payloads, access other than asked for). Returns the previous level; a
 * level of -1 only asks for the current one.
 */
int player_debug_level(int level);

/*
 * Connects to the server at host:port and reads its banner into conn.
 * Returns 0 (connected) or -1 (not connected: conn->sock is -1).
 */
int player_connect(player_connection_t* conn, const char* host, int port);

/*
 * Closes the connection. Returns 0, or -1 if conn was not connected.
 */
int player_disconnect(player_connection_t* conn);

/*
 * Asks for req_access ('r', 'w', 'a' or 'c') to a device. The access granted
 * ('e' when the server has no such device or could not open it) goes to
 * *grant_access unless grant_access is NULL. Returns 0 when the server
 * answered, -1 otherwise (you should probably close the connection).
 */
int player_request_device_access(player_connection_t* conn,
                                 uint16_t device,
                                 uint16_t device_index,
                                 uint8_t req_access,
                                 uint8_t* grant_access);

/*
 * Reads the next message of any type (data, SYNCH, a reply), blocking until
 * one comes. The header goes to *hdr in host order; the first payloadlen
 * bytes of the payload go to payload, untouched (network order). A longer
 * payload is cut to payloadlen; hdr->size still tells its real length.
 * Returns 0, or -1 (you should probably close the connection).
 */
int player_read(player_connection_t* conn, player_msghdr_t* hdr,
                char* payload, size_t payloadlen);

/*
 * Sends the first commandlen bytes of command (network order) as a command
 * to the device. Returns 0, or -1 (nothing sent when commandlen exceeds
 * PLAYER_MAX_PAYLOAD_SIZE).
 */
int player_write(player_connection_t* conn,
                 uint16_t device, uint16_t device_index,
                 const char* command, size_t commandlen);

/*
 * Sends a request (payload in network order) and waits for its reply: the
 * first ACK, NACK or ERR for that device and index. The reply header goes to
 * *replyhdr (host order) and up to replylen bytes of its payload to reply,
 * each only if non-NULL; a longer reply is cut to replylen. A NACK or ERR
 * still returns 0: look at replyhdr->type. Returns -1 when no reply came,
 * or when the payload is NULL, empty or longer than PLAYER_MAX_PAYLOAD_SIZE
 * (then nothing is sent: a 1.5 server never answers an empty request).
 */
int player_request(player_connection_t* conn,
                   uint16_t device, uint16_t device_index,
                   const char* payload, size_t payloadlen,
                   player_msghdr_t* replyhdr, char* reply, size_t replylen);

#ifdef __cplusplus
}
#endif

#endif /* PLAYERKIT_PLAYERCCLIENT_H */
