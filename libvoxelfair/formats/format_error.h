// Readers report malformed input by throwing FormatError (base/error.h). The message says what is
// wrong and where (byte offset, section, column); the caller prefixes the file's name.
#pragma once

#include "base/error.h"
