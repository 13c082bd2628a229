// depth.frag: shadow casters drawn into the sun's cascades write depth only.
void main() {}
