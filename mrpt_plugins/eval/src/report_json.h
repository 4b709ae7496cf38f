/* rfir_eval: a result row as a JSON value, for the documents of this library
 * that hold rows (toJson, toJsonRuns). */
#pragma once

#include <rfir/common/json.h>
#include <rfir/eval/report.h>

namespace rfir::eval {
rfir::common::TJson toJsonValue(const TEvalResult& r);
}  // namespace rfir::eval
