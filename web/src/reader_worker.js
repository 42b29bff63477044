// Reads files of the server's root off the page's thread, as they download: a 40 × 40
// Miura-ori's fold is 49 MB and 309,000 <Fold> elements, 0.3–0.4 s of reading that would
// otherwise wait for, and then hold up, the page's thread while three.js loads and the pattern is
// read. Messages in: {boot: true} (sendCommandLine) or {read: PATH} (sendSequence); the answers
// are reader_tasks.js's.
import { sendCommandLine, sendSequence } from './reader_tasks.js';

const post = (answer, transfer = []) => self.postMessage(answer, transfer);
self.onmessage = ({ data }) => (data.boot ? sendCommandLine(post) : sendSequence(data.read, post));
