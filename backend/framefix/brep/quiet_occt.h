#pragma once
// Silencing OCCT's message printers for one call (internal to brep/).
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

namespace framefix {

// OCCT's readers and writers print diagnostics on stdout, which belongs to the CLI's summary. The printers
// are taken off for one read and put back after, so a host (FreeCAD) keeps its own.
class QuietOcct {
public:
    QuietOcct() : saved_(Message::DefaultMessenger()->Printers()) {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    }
    ~QuietOcct() { Message::DefaultMessenger()->ChangePrinters() = saved_; }
    QuietOcct(const QuietOcct&) = delete;
    QuietOcct& operator=(const QuietOcct&) = delete;

private:
    Message_SequenceOfPrinters saved_;
};

}  // namespace framefix
