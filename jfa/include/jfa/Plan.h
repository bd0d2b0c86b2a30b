#pragma once
// Placeholder: replaced by the plans implementation.
namespace fl::jfa {}
