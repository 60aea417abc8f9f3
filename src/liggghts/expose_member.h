// Access to a member LIGGGHTS keeps private, by explicit instantiation (why this way and not
// another: liggghts_members.cpp). Per member: a tag struct with `using type = <member pointer
// type>;` and `friend type member(Tag);`, then, once in the program,
// `template struct ExposeMember<Tag, &Class::member_>;`; `obj->*member(Tag{})` reaches it.
#pragma once

namespace hardcontact {
namespace liggghts {
// unnamed, as the tags of each file that uses it: the friend it defines must live in the tags'
// namespace
namespace {

template <typename Tag, typename Tag::type Member>
struct ExposeMember {
  friend typename Tag::type member(Tag) { return Member; }
};

}    // namespace
}    // namespace liggghts
}    // namespace hardcontact
