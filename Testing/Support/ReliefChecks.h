#ifndef ReliefChecks_h
#define ReliefChecks_h

#include <iostream>
#include <string>

// The checks of a regression test that asserts several properties of one scene: each
// said when it fails, and whether all held. Header only.
class ReliefChecks
{
public:
  void operator()(bool condition, const std::string& what)
  {
    if (!condition)
    {
      std::cerr << "FAILED: " << what << "\n";
      ++this->Failures;
    }
  }
  bool Passed() const { return this->Failures == 0; }

private:
  int Failures = 0;
};

#endif
