// Compiles nothing of its own: the target around it builds the precompiled
// header every test program reuses (cmake/PlayerkitTest.cmake).
