#include <jfa/Plan.h>
