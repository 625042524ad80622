#include "mesowave/app/superposition_options.hpp"

namespace mesowave::app {

CLI::Option* add_superposition_options(CLI::App& command, CLI::Option* single_frequency,
                                       const SuperpositionOptionText& text, std::vector<double>& frequencies_kHz,
                                       std::string& signals_pattern, std::string& record_pattern,
                                       std::vector<double>& check_kHz) {
  auto* many = command.add_option("--frequencies-kHz", frequencies_kHz,
                                  "Burst centre frequencies [kHz] (comma-separated) from one " + text.method)
                   ->delimiter(',')
                   ->excludes(single_frequency);
  command.add_option("--signals-pattern", signals_pattern,
                     "With --frequencies-kHz: each frequency's signals, {f} the frequency in kHz ('" +
                         text.signals_example + "')")
      ->needs(many);
  command.add_option(text.record_option, record_pattern,
                     "With --frequencies-kHz: each frequency's " + text.record_noun + " (JSON), {f} as above")
      ->needs(many);
  command.add_option("--check-kHz", check_kHz,
                     "With --frequencies-kHz: also run these of them directly (comma-separated) and record the "
                     "superposition's PCC and largest difference / peak against each in the " + text.record_noun +
                         " files")
      ->delimiter(',')
      ->needs(many);
  return many;
}

}  // namespace mesowave::app
