// A small element-only XML reader: enough for PMML, and it works in node (no DOMParser).

const NAME = /[A-Za-z_:][-A-Za-z0-9_.:]*/y;
const ENTITY = /&(#x[0-9a-fA-F]+|#[0-9]+|amp|lt|gt|quot|apos);/y;
const NAMED = { amp: '&', lt: '<', gt: '>', quot: '"', apos: "'" };

class XmlReader {
  constructor(text) {
    this.text = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
    this.pos = 0;
    this.newlines = [];
    for (let i = this.text.indexOf('\n'); i >= 0; i = this.text.indexOf('\n', i + 1)) this.newlines.push(i);
  }

  lineAt(pos) {
    let lo = 0, hi = this.newlines.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.newlines[mid] < pos) lo = mid + 1;
      else hi = mid;
    }
    return lo + 1;
  }

  fail(pos, message) {
    throw new Error(`${this.lineAt(pos)}: ${message}`);
  }

  startsWith(s) {
    return this.text.startsWith(s, this.pos);
  }

  skipPast(close, what) {
    const end = this.text.indexOf(close, this.pos);
    if (end < 0) this.fail(this.pos, `unterminated ${what}`);
    this.pos = end + close.length;
  }

  skipSpace() {
    while (this.pos < this.text.length && ' \t\r\n'.includes(this.text[this.pos])) ++this.pos;
  }

  name() {
    NAME.lastIndex = this.pos;
    const m = NAME.exec(this.text);
    if (!m) this.fail(this.pos, `expected a name after '${this.text.slice(this.pos - 1, this.pos)}'`);
    this.pos += m[0].length;
    return m[0];
  }

  decode(raw, at) {
    if (!raw.includes('&')) return raw;
    let out = '';
    for (let i = 0; i < raw.length; ) {
      const amp = raw.indexOf('&', i);
      if (amp < 0) {
        out += raw.slice(i);
        break;
      }
      out += raw.slice(i, amp);
      ENTITY.lastIndex = amp;
      const m = ENTITY.exec(raw);
      if (!m) this.fail(at + amp, `bad entity reference '${raw.slice(amp, amp + 12)}'`);
      const body = m[1];
      if (body[0] === '#') {
        const code = body[1] === 'x' ? parseInt(body.slice(2), 16) : parseInt(body.slice(1), 10);
        if (!(code > 0 && code <= 0x10ffff) || (code >= 0xd800 && code <= 0xdfff))
          this.fail(at + amp, `character reference '${m[0]}' is not allowed`);
        out += String.fromCodePoint(code);
      } else out += NAMED[body];
      i = amp + m[0].length;
    }
    return out;
  }

  // Comments, processing instructions and a DOCTYPE may stand around the root element.
  skipMisc() {
    for (;;) {
      this.skipSpace();
      if (this.startsWith('<!--')) this.skipPast('-->', 'comment');
      else if (this.startsWith('<?')) this.skipPast('?>', 'processing instruction');
      else if (this.startsWith('<!DOCTYPE')) {
        const close = this.text.indexOf('>', this.pos), bracket = this.text.indexOf('[', this.pos);
        if (bracket >= 0 && (close < 0 || bracket < close)) this.skipPast(']>', 'DOCTYPE');
        else this.skipPast('>', 'DOCTYPE');
      } else return;
    }
  }

  attributes(el) {
    for (;;) {
      const before = this.pos;
      this.skipSpace();
      const c = this.text[this.pos];
      if (c === '>' || (c === '/' && this.text[this.pos + 1] === '>') || c === undefined) return;
      if (this.pos === before) this.fail(this.pos, `expected '>' in <${el.name}>`);
      const attr = this.name();
      this.skipSpace();
      if (this.text[this.pos] !== '=') this.fail(this.pos, `attribute '${attr}' of <${el.name}> has no value`);
      ++this.pos;
      this.skipSpace();
      const q = this.text[this.pos];
      if (q !== '"' && q !== "'") this.fail(this.pos, `attribute '${attr}' of <${el.name}> is not quoted`);
      const end = this.text.indexOf(q, this.pos + 1);
      if (end < 0) this.fail(this.pos, `unterminated attribute '${attr}'`);
      el.attributes[attr] = this.decode(this.text.slice(this.pos + 1, end), this.pos + 1);
      this.pos = end + 1;
    }
  }

  /** The root element: {name, attributes, children, text, line}. */
  parse() {
    this.skipMisc();
    if (this.pos >= this.text.length) this.fail(this.pos, 'the file is empty');
    if (this.text[this.pos] !== '<') this.fail(this.pos, 'text before the root element');
    const stack = [];
    let root = null;
    while (this.pos < this.text.length) {
      const top = stack[stack.length - 1];
      if (this.text[this.pos] !== '<') {
        let end = this.text.indexOf('<', this.pos);
        if (end < 0) end = this.text.length;
        top.text += this.decode(this.text.slice(this.pos, end), this.pos);
        top.hasText ||= /\S/.test(this.text.slice(this.pos, end));
        this.pos = end;
      } else if (this.startsWith('<!--')) this.skipPast('-->', 'comment');
      else if (this.startsWith('<![CDATA[')) {
        const start = this.pos + 9;
        this.skipPast(']]>', 'CDATA section');
        top.text += this.text.slice(start, this.pos - 3);
        top.hasText = true;
      } else if (this.startsWith('<?')) this.skipPast('?>', 'processing instruction');
      else if (this.startsWith('</')) {
        const at = this.pos;
        this.pos += 2;
        const name = this.name();
        this.skipSpace();
        if (this.text[this.pos] !== '>') this.fail(this.pos, `expected '>' after </${name}`);
        ++this.pos;
        if (name !== top.name) this.fail(at, `expected </${top.name}> (opened at line ${top.line}), found </${name}>`);
        stack.pop();
        if (!stack.length) break;
      } else if (this.startsWith('<!')) this.fail(this.pos, "unexpected '<!'");
      else {
        const at = this.pos;
        ++this.pos;
        const el = { name: this.name(), attributes: {}, children: [], text: '', hasText: false, line: this.lineAt(at) };
        this.attributes(el);
        if (this.pos >= this.text.length) this.fail(at, `unterminated start tag <${el.name}>`);
        if (top) top.children.push(el);
        else root = el;
        if (this.text[this.pos] === '/') this.pos += 2;
        else {
          ++this.pos;
          stack.push(el);
        }
        if (!stack.length) break;
      }
    }
    if (stack.length) {
      const open = stack[stack.length - 1];
      throw new Error(`${open.line}: <${open.name}> is not closed`);
    }
    this.skipMisc();
    if (this.pos < this.text.length) this.fail(this.pos, 'content after the root element');
    return root;
  }
}

/** Parse XML text into {name, attributes, children, text, line} elements; throws Error('LINE: message'). */
export function parseXml(text) {
  return new XmlReader(String(text)).parse();
}
