// Kept while the adapter moves to dual_operator.h (contact_forces lives there now).
#pragma once
#include "dual_operator.h"
