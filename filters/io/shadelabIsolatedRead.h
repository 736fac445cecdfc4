/**
 * @brief   a reading step run in a child process, so that a library's crash is an error
 *
 * assimp 5.2's COLLADA and DirectX parsers crash on some malformed files
 * (fuzzing found segmentation faults inside libassimp.so), and a crash in
 * shadelab's process would end the program: a batch's later shots, or the
 * window, with it. ReadIsolated forks; the child runs `read` and sends back
 * the bytes it returns, or the error it threw; the parent waits and returns
 * those bytes or throws that error. A child that dies of a signal, or ends
 * without an answer, is the one-line MeshReadError
 * "<who> crashed reading it (SIGSEGV)".
 *
 * The child is a copy of the parent, so `read` sees everything the parent
 * has (the file's bytes already read, say) without copying it. In the child:
 * stdout and stderr go to /dev/null (a library's own prints never reach the
 * program's one line per problem); SIGINT and SIGTERM are ignored, so that
 * an interruption is the parent's alone, as for a read in the parent; it
 * dies with the parent (PR_SET_PDEATHSIG); it ends with _exit, running no
 * destructor and no exit handler of the parent's (nor LeakSanitizer's, so
 * the library's leaks on a malformed file end with the child unseen).
 * `read` must touch nothing of the parent's but memory and files: the
 * parent's other threads are not in the child (the window reads on a
 * worker thread), and a lock one of them held stays held there.
 */
#ifndef shadelabIsolatedRead_h
#define shadelabIsolatedRead_h

#include <functional>
#include <string>

namespace shadelab
{
/**
 * What `read` returns, computed in a child process. Throws MeshReadError:
 * the one `read` threw in the child (its message and code; out of memory
 * and other exceptions as vtkShadelabFileReader reports them), "<who>
 * crashed reading it (SIGNAL)" or "(exit status N)" when the child ended
 * without an answer, and an error naming the system call when no child
 * could be made.
 */
std::string ReadIsolated(const char* who, const std::function<std::string()>& read);
}

#endif
