// Hostile outputs: no command writes over one of its own inputs, and an output that cannot be
// written is refused before the work, in hmcr's words.
#include "tests/hostile/hostile.h"

namespace hmcr::test {
namespace {

TEST_F(Hostile, NoCommandWritesOverItsInputs) {
    plates();
    // solve's summary goes beside the .vtp: plates.vtp would put it over plates.json.
    refused("solve plates.json -o plates.vtp", "is an input of this command");
    refused("solve plates.obj -o plates.obj", "output must be a .vtp file");
    accepted("solve plates.json --rays 2000 -q -o p.vtp");
    refused("render p.vtp --scene plates.json -o p.png --pfm p.vtp", "must be a .pfm file");
    m_temp.write("same.png", "");
    refused("render p.vtp --scene plates.json -o x.png --pfm x.png", "must be a .pfm file");
    std::filesystem::create_symlink(dir() / "p.vtp", dir() / "link.pfm");
    refused("render p.vtp --scene plates.json -o x.png --pfm link.pfm", "is an input");
}

TEST_F(Hostile, AStudyMayNotWriteIntoItsReference) {
    plates();
    std::filesystem::create_directories(dir() / "ref");
    const std::string study = "study plates.json --budgets 5 --oracles power --reference ref ";
    refused(study + "-o ref", "is, holds or lies in the input folder");
    refused(study + "-o ref/inside", "is, holds or lies in the input folder");
    refused(study + "-o .", "is, holds or lies in the input folder");
}

TEST_F(Hostile, OutputsThatCannotBeWrittenAreRefusedFirst) {
    plates();
    m_temp.write("file", "x");
    refused("reference plates.json --rays 100000000 -o file", "cannot write file: it is not a folder");
    refused("study plates.json --budgets 5 --reference ref -o file", "it is not a folder");
    refused("solve plates.json --rays 100000000 -o /proc/x.vtp", "cannot write /proc/x.vtp");
    refused("solve plates.json -o file/x.vtp", "cannot write file/x.vtp");
    std::filesystem::create_directory(dir() / "x.vtp");
    refused("solve plates.json -o x.vtp", "it is a folder");
}

}  // namespace
}  // namespace hmcr::test
