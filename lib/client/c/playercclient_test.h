/*
 * The C side of playercclient_test: checks written in C against
 * playercclient.h, run by a GoogleTest harness that owns a real server.
 * Each check returns NULL when it passes, or a description of the first
 * thing that did not hold.
 */
#ifndef PLAYERKIT_PLAYERCCLIENT_TEST_H
#define PLAYERKIT_PLAYERCCLIENT_TEST_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * What the checks may ask of the server, which serves
 *   laser:0 (source)  position:0 (actuator)  sonar:0 (echo)   and no ptz.
 * Hooks return 0 when done, -1 when the harness could not do it.
 */
typedef struct pcc_server {
  int port;
  void* context;
  /* The laser's source driver publishes these bytes with this timestamp. */
  int (*publish_laser)(void* context, const unsigned char* bytes, size_t length,
                       uint32_t timestamp_sec, uint32_t timestamp_usec);
  /* Waits (5 s at most) for a command on position:0 and copies up to
   * capacity bytes of it. The server replaces it with a stop command when
   * the last client leaves: ask before disconnecting. */
  int (*position_command)(void* context, unsigned char* bytes, size_t capacity, size_t* length);
  /* Stops the server, closing every connection. */
  int (*stop)(void* context);
} pcc_server;

/* playercclient_test.c (C99) */
const char* pcc_check_connect_reads_banner_and_socket(const pcc_server* server);
const char* pcc_check_connect_failures(void);
const char* pcc_check_device_access(const pcc_server* server);
const char* pcc_check_read_data_header_in_host_order(const pcc_server* server);
const char* pcc_check_read_cuts_long_payloads(const pcc_server* server);
const char* pcc_check_write_command(const pcc_server* server);
const char* pcc_check_write_refuses_bad_commands(const pcc_server* server);
const char* pcc_check_request_and_replies(const pcc_server* server);
const char* pcc_check_request_refuses_bad_payloads(const pcc_server* server);
const char* pcc_check_use_after_disconnect(const pcc_server* server);
const char* pcc_check_lost_connection(const pcc_server* server);
const char* pcc_check_debug_level(void);
const char* pcc_check_diagnostics_follow_debug_level(const pcc_server* server);

/* playercclient_c89_check.c (strict C89) */
const char* pcc_c89_check_struct_layouts(void);
/* The fragments of appendix A, as one 2004 program. */
const char* pcc_c89_appendix_example(const pcc_server* server);

#ifdef __cplusplus
}
#endif

#endif /* PLAYERKIT_PLAYERCCLIENT_TEST_H */
