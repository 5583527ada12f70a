'' Child of fall_off_value.spin: a procedure whose value the parent uses.
VAR
  long stopped
PUB stop
  stopped := TRUE
